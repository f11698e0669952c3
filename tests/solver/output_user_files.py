# A run never deletes files it (or an earlier run, by its list
# .fosls-contact-files) did not write: the user's files put into
# Output/Directory after a first run (solution_0001.vtu, solution_abc.vtu,
# solution_0000.2.vtu, notes.txt and a subdirectory, named like output
# files or not) are carried over into the new directory with their content, while the pieces
# an earlier run wrote and this one does not (solution_0000.1.vtu after a
# run on 2 processes) are removed, as is the .pvtu when Write vtu = false.
# ctest: timeout=120 mpirun
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, command_line, execute, finish, leftovers, one_error_line

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")
directory = "out"
user = {"solution_0001.vtu": "a", "solution_abc.vtu": "b", "solution_0000.2.vtu": "c",
        "notes.txt": "d", "plots/p.txt": "e"}

def add_user_files():
    os.makedirs(os.path.join(directory, "plots"))
    for name, content in user.items():
        with open(os.path.join(directory, name), "w") as f:
            f.write(content)



def user_files_intact():
    try:
        return all(open(os.path.join(directory, n)).read() == c for n, c in user.items())
    except OSError:
        return False


def solution_files():
    return sorted(f for f in os.listdir(directory) if f.startswith("solution_0000.")
                  and f != "solution_0000.2.vtu")


def listed_pieces():
    with open(os.path.join(directory, "solution_0000.pvtu")) as f:
        return sorted(re.findall(r'Source="([^"]+)"', f.read()))


# a directory with other files than output files, not written by the
# program, is refused (the run would replace it)
add_user_files()
rc, out, err = execute([exe, scene, "--set", "Output/Directory=" + directory])
check(rc == 1 and one_error_line(err, "Output/Directory", "did not write")
      and user_files_intact(), "a directory the program did not write: refused, files intact")
shutil.rmtree(directory)

first = True
for label, processes, extra in [("1 process", 1, []), ("2 processes", 2, []),
                                ("1 process", 1, []),
                                ("Write vtu = false", 1, ["Output/Write vtu=false"])]:
    rc, out, err = execute(command_line(
        exe, scene, ["Output/Directory=" + directory, "Geometry/Levels=2",
                     "Output/Verbose=false"] + extra, processes))
    if first:
        add_user_files()
        first = False
        continue
    files = solution_files()
    print("--- %s: %s" % (label, " ".join(files)))
    check(rc == 0 and err == "", label + ": exit code 0, nothing on stderr")
    check(user_files_intact(), label + ": the user's files are there with their content")
    if extra:
        check(files == [], label + ": the earlier run's solution files are removed")
    else:
        check(files == sorted(listed_pieces() + ["solution_0000.pvtu"]),
              label + ": this run's solution files are the .pvtu and the pieces it lists")
    check(leftovers(directory) == [], label + ": no staging directory or lock file left")
finish()
