# Shared start of the bench/*_table.sh scripts (sourced): work from the repository root with
# the command-line tool built and bench/results present; `meshes` takes the script's
# arguments, or the defaults given to bench_meshes when there are none.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
[ -x build/apps/sphereset ] || cmake --build build --target sphereset_cli
mkdir -p bench/results
bench_meshes() {
  if [ ${#args[@]} -gt 0 ]; then meshes=("${args[@]}"); else meshes=("$@"); fi
}
