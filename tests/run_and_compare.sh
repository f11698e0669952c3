#!/bin/bash
# The one test driver of tests/CMakeLists.txt. Three modes:
#
#   run_and_compare.sh unit  WORKDIR EXPECTED REL ABS -- EXE [ARGS...]
#       Runs a unit test executable in a fresh WORKDIR; it must exit with 0,
#       and its standard output must match EXPECTED (numdiff, relative
#       tolerance REL, absolute tolerance ABS). The solver and fuzz tests
#       use this mode with EXE = python3 tests/<kind>/<name>.py FOSLS_CONTACT
#       SRC.
#
#   run_and_compare.sh scene WORKDIR EXPECTED REL ABS FILTER -- EXE PRM [ARGS...]
#       Runs `EXE PRM --set Output/Directory=out ARGS...` in a fresh WORKDIR
#       (prefixed by $FOSLS_LAUNCH if set, e.g. "mpirun -np 2"); it must
#       exit with 0 and print nothing on stderr. FILTER (python3) turns the
#       screen output and the output directory into deterministic text that
#       must match EXPECTED (numdiff as above).
#
#   run_and_compare.sh bad   WORKDIR TEST PROCESSES FOSLS_CONTACT
#       Runs the command of the bad-input test file TEST in a fresh, empty
#       WORKDIR/run; it must exit with 1 (an error all processes decide),
#       print exactly one line on stderr that matches the extended regular
#       expression of TEST, and write nothing: WORKDIR/run must still be
#       empty afterwards. TEST holds comment lines (#), one line
#       `error: REGEX` and one or more lines `run: COMMAND...` (joined
#       into one bash command). The command runs with the variables of
#       tests/bad_input/shared_scenes.sh, $src (the repository), $tests, $bad
#       (tests/bad_input), $mpirun, $fosls_binary (FOSLS_CONTACT) and the
#       function `fosls`, which runs FOSLS_CONTACT with its arguments, on
#       PROCESSES MPI processes if PROCESSES > 1 (mpirun --quiet: without
#       mpirun's own report of the non-zero exit on stderr).
#
# numdiff, python3 and mpirun are taken from $NUMDIFF, $PYTHON and $MPIRUN
# if set (ctest sets them), else from PATH.
#
# To regenerate an expected file after checking the new numbers,
# copy WORKDIR/output over it (never blindly).
set -u
NUMDIFF=${NUMDIFF:-numdiff}
PYTHON=${PYTHON:-python3}

fail() {
  echo "FAILED: $*"
  exit 1
}

mode=$1
workdir=$2
shift 2

numdiff_compare() { # expected actual rel abs
  if ! "$NUMDIFF" -q -r "$3" -a "$4" "$1" "$2" > /dev/null 2>&1; then
    echo "--- expected: $1"
    echo "--- actual:   $2"
    "$NUMDIFF" -V -r "$3" -a "$4" "$1" "$2" | head -60
    fail "output differs from $1"
  fi
}

case "$mode" in
  unit)
    expected=$1 rel=$2 abs=$3
    shift 3
    [ "$1" = "--" ] || fail "usage"
    shift
    rm -rf "$workdir" && mkdir -p "$workdir" && cd "$workdir" || fail "cannot create $workdir"
    "$@" > output 2> stderr
    rc=$?
    cat output
    cat stderr >&2
    [ $rc -eq 0 ] || fail "exit code $rc"
    numdiff_compare "$expected" "$workdir/output" "$rel" "$abs"
    ;;

  scene)
    expected=$1 rel=$2 abs=$3 filter=$4
    shift 4
    [ "$1" = "--" ] || fail "usage"
    shift
    exe=$1 prm=$2
    shift 2
    rm -rf "$workdir" && mkdir -p "$workdir" && cd "$workdir" || fail "cannot create $workdir"
    # shellcheck disable=SC2086
    ${FOSLS_LAUNCH:-} "$exe" "$prm" --set "Output/Directory=out" "$@" > screen 2> stderr
    rc=$?
    tail -n 25 screen
    [ $rc -eq 0 ] || { cat stderr; fail "exit code $rc"; }
    [ -s stderr ] && { cat stderr; fail "the run printed on stderr"; }
    [ -d out ] || fail "no output directory"
    "$PYTHON" "$filter" screen out > output || fail "filter failed"
    cat output
    numdiff_compare "$expected" "$workdir/output" "$rel" "$abs"
    ;;

  bad)
    test_file=$1 processes=$2 fosls_binary=$3
    regex= command=
    while IFS= read -r line; do
      case "$line" in
        "#"* | "") ;;
        "error: "*) regex=${line#error: } ;;
        "run: "*) command+=" ${line#run: }" ;;
        *) fail "$test_file: a line that is not a comment, 'error: REGEX' or 'run: COMMAND': $line" ;;
      esac
    done < "$test_file"
    [ -n "$regex" ] && [ -n "$command" ] || fail "$test_file: no 'error:' or no 'run:' line"
    bad=$(cd "$(dirname "$test_file")" && pwd)
    tests=$(dirname "$bad")
    src=$(dirname "$tests")
    mpirun=${MPIRUN:-mpirun}
    fosls() {
      if [ "$processes" -gt 1 ]; then
        "$mpirun" --quiet --oversubscribe -np "$processes" "$fosls_binary" "$@"
      else
        "$fosls_binary" "$@"
      fi
    }
    # shellcheck source=bad_input/shared_scenes.sh
    . "$bad/shared_scenes.sh"
    rm -rf "$workdir" && mkdir -p "$workdir/run" && cd "$workdir/run" || fail "cannot create $workdir"
    eval "$command" > ../stdout 2> ../stderr
    rc=$?
    echo "exit code: $rc"
    echo "stderr:"
    cat ../stderr
    [ $rc -ne 0 ] || fail "the program accepted the bad input (exit code 0)"
    [ $rc -lt 128 ] || fail "the program died by a signal (exit code $rc)"
    # (3: an error that some MPI processes met alone, the run aborted)
    [ $rc -eq 1 ] || fail "expected exit code 1 (an error all processes decide), got $rc"
    lines=$(wc -l < ../stderr)
    [ "$lines" -eq 1 ] || fail "expected exactly one line on stderr, got $lines"
    grep -Eq -- "$regex" ../stderr || fail "stderr does not match /$regex/"
    leftovers=$(ls -A)
    [ -z "$leftovers" ] || fail "the run wrote files: $leftovers"
    echo "ok: one line on stderr matching /$regex/, nothing written"
    ;;

  *)
    fail "unknown mode $mode"
    ;;
esac
exit 0
