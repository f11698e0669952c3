# The scenes the bad-input tests share, for the run: lines of
# tests/bad_input/*.test (sourced by tests/run_and_compare.sh, which sets
# $src, the repository, $tests, its tests/, and $bad, this folder).

square=$tests/scenes/square.prm
quarter=$src/prm/quarter_ball_file.prm

# the half disc of prm/hertz.prm from a mesh file (given by the test with
# --set "Geometry/Mesh file=..."), clamped on top, in contact below
disc_file=("$src/prm/hertz.prm" --set "Geometry/Shape=file"
           --set "Boundary conditions/Dirichlet boundary ids=2"
           --set "Boundary conditions/Contact boundary ids=1")
# the whole boundary clamped (a mesh file with boundary id 0 only)
clamped=(--set "Boundary conditions/Dirichlet boundary ids=0"
         --set "Boundary conditions/Neumann boundary ids="
         --set "Boundary conditions/Contact boundary ids=")
disc_clamped=("${disc_file[@]}" "${clamped[@]}")
cube_file=("$tests/scenes/cube3d.prm" --set "Geometry/Shape=file" "${clamped[@]}")
# a mesh file of two parts, given by the test with its contact ids: id 1
# clamped, id 0 free
two_parts=("$square" --set "Geometry/Shape=file" --set "Geometry/Levels=3"
           --set "Boundary conditions/Dirichlet boundary ids=1"
           --set "Boundary conditions/Neumann boundary ids=0")
# the square with friction, solved by the active set method (the law and
# its data given by the test)
friction=("$square" --set "Solver/Type=active set")
