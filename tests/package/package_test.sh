#!/usr/bin/env bash
# ctest package: the installed package works for a user, outside this tree.
#   (a) installs the built project into WORK/prefix (cmake --install) and
#       checks what is there: every public header and nothing private, both
#       static libraries, the CMake package, manyworlds.pc; no Eigen asked of
#       users; each installed header compiles on its own, seeing only the
#       prefix and the standard library;
#   (b) configures, builds and runs tests/package/consumer with
#       find_package(manyworlds) against the prefix (CMAKE_PREFIX_PATH);
#   (c) builds and runs the same program with plain c++ and pkg-config
#       (PKG_CONFIG_PATH), warnings as errors;
#   (d) extracts the README's complete example (the ```cpp block after the
#       marker line below) and builds it exactly as written in (b), then
#       runs it, so README and test cannot drift;
#   (e) with MPIEXEC (a build with the MPI layer, mpi/): the MPI header,
#       library and export are installed too, and the consumer's
#       ShardedBatch program (find_package gives manyworlds::mpi) builds and
#       runs under MPIEXEC with 2 ranks.
# Usage: package_test.sh SOURCE_DIR BUILD_DIR WORK_DIR LIBDIR INCLUDEDIR
#                        CMAKE CXX PKG_CONFIG VERSION [CONFIG [MPIEXEC]]
set -euo pipefail
source_dir=$1 build_dir=$2 work=$3 libdir=$4 includedir=$5
cmake=$6 cxx=$7 pkg_config=$8 version=$9 config=${10:-} mpiexec=${11:-}
marker='<!-- package-test: the README example -->'

fail() { echo "package_test: $*" >&2; exit 1; }
step() { echo "package_test: $*"; }

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

# ---- (a) install and check what was installed
step "installing $build_dir into $prefix"
config_args=()
[ -n "$config" ] && config_args=(--config "$config")
"$cmake" --install "$build_dir" --prefix "$prefix" "${config_args[@]}" >"$work/install.log" ||
  { cat "$work/install.log" >&2; fail "cmake --install failed"; }

# Every public header, and nothing but them under include/ (with MPI, the
# MPI layer's header too).
expected_headers=$( (cd "$source_dir/include" && find manyworlds -name '*.h'
                     if [ -n "$mpiexec" ]; then
                       cd "$source_dir/mpi/include" && find manyworlds -name '*.h'
                     fi) | sort)
installed_headers=$(cd "$prefix/$includedir" && find . -type f | sed 's|^\./||' | sort)
[ -n "$expected_headers" ] || fail "no headers in $source_dir/include/manyworlds"
[ "$expected_headers" = "$installed_headers" ] ||
  fail "installed headers differ from include/manyworlds:
$(diff <(echo "$expected_headers") <(echo "$installed_headers") || true)"

cmake_dir=$prefix/$libdir/cmake/manyworlds
for file in "$libdir/libmanyworlds_batch.a" "$libdir/libmanyworlds_kernels.a" \
            "$libdir/cmake/manyworlds/manyworldsConfig.cmake" \
            "$libdir/cmake/manyworlds/manyworldsConfigVersion.cmake" \
            "$libdir/cmake/manyworlds/manyworldsTargets.cmake" \
            "$libdir/pkgconfig/manyworlds.pc"; do
  [ -s "$prefix/$file" ] || fail "$file not installed"
done
libraries='batch|kernels' exports='Targets|Targets-[a-z]+'
if [ -n "$mpiexec" ]; then
  for file in "$libdir/libmanyworlds_mpi.a" "$libdir/cmake/manyworlds/manyworldsMpiTargets.cmake"; do
    [ -s "$prefix/$file" ] || fail "$file not installed (a build with MPI)"
  done
  libraries='batch|kernels|mpi' exports='Targets|Targets-[a-z]+|MpiTargets|MpiTargets-[a-z]+'
fi
# Nothing else of the C++ package: no private headers, other libraries or
# stray CMake files. (Files elsewhere, e.g. a Python module's, are not this
# test's business.)
unexpected=$(cd "$prefix" && find . -type f | sed 's|^\./||' |
  grep -E "^$includedir/|^$libdir/[^/]+$|^$libdir/cmake/|^$libdir/pkgconfig/" | grep -v -E \
  "^$includedir/manyworlds/[a-z_]+\.h$|^$libdir/libmanyworlds_($libraries)\.a$|^$libdir/cmake/manyworlds/manyworlds(Config|ConfigVersion|$exports)\.cmake$|^$libdir/pkgconfig/manyworlds\.pc$" || true)
[ -z "$unexpected" ] || fail "unexpected files installed:
$unexpected"

# Eigen is private to the library: neither the CMake package nor the .pc may
# ask a user for it (comments aside).
if grep -i -H eigen "$cmake_dir"/*.cmake "$prefix/$libdir/pkgconfig/manyworlds.pc" |
     grep -v -E '^[^:]+:[[:space:]]*#'; then
  fail "the installed package asks for Eigen (above)"
fi
# Nothing installed may point back into the source or build tree.
if grep -l -F -e "$source_dir" -e "$build_dir" "$cmake_dir"/*.cmake \
     "$prefix/$libdir/pkgconfig/manyworlds.pc"; then
  fail "the installed package refers to the source or build tree (above)"
fi

# The installed API is include/manyworlds alone: every #include of a public
# header is a standard header or another public header (or MPI's, in the MPI
# layer's), and each header
# compiles on its own with only the prefix on the include path.
bad_includes=$(grep -H -E '^[[:space:]]*#[[:space:]]*include' "$prefix/$includedir"/manyworlds/*.h |
  grep -v -E '#[[:space:]]*include[[:space:]]+(<[a-z_]+>|"manyworlds/[a-z_]+\.h")' |
  grep -v -E '/manyworlds/sharded_batch\.h:#[[:space:]]*include[[:space:]]+<mpi\.h>' || true)
[ -z "$bad_includes" ] || fail "public headers include something outside the API:
$bad_includes"
# The MPI layer's header also sees MPI's own (the flags of MPI's mpicxx).
mpi_cflags=()
if [ -n "$mpiexec" ]; then
  read -r -a mpi_cflags < <("$(dirname "$mpiexec")/mpicxx" --showme:compile)
fi
for header in "$prefix/$includedir"/manyworlds/*.h; do
  name=manyworlds/$(basename "$header")
  extra=()
  [ "$name" = manyworlds/sharded_batch.h ] && extra=("${mpi_cflags[@]}")
  printf '#include "%s"\n' "$name" |
    "$cxx" -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Werror \
      -I"$prefix/$includedir" "${extra[@]}" -x c++ - ||
    fail "$name does not compile on its own"
done
step "installed: $(echo "$installed_headers" | wc -l) headers, 2 libraries, CMake package, manyworlds.pc; headers self-contained"

# ---- (d, first half) the README's complete example, as written
readme_example=$work/readme_example.cc
awk -v marker="$marker" '
  $0 == marker { found = 1; next }
  found == 1 && /^```cpp[[:space:]]*$/ { found = 2; next }
  found == 1 && NF { found = -1; exit }   # something else between marker and fence
  found == 2 && /^```[[:space:]]*$/ { found = 3; exit }
  found == 2 { print }
  END { if (found != 3) exit (found == 0 ? 1 : found == -1 ? 3 : 2) }' \
  "$source_dir/README.md" >"$readme_example" || {
  case $? in
    1) fail "README.md has no line '$marker'" ;;
    2) fail "README.md: no closed \`\`\`cpp block after '$marker'" ;;
    *) fail "README.md: '$marker' must be followed by a \`\`\`cpp block" ;;
  esac
}
grep -q 'int main' "$readme_example" || fail "the README example has no main"
step "README example: $(wc -l <"$readme_example") lines extracted"

# ---- (b) find_package(manyworlds) from an outside project
step "configuring and building tests/package/consumer with find_package(manyworlds)"
"$cmake" -S "$source_dir/tests/package/consumer" -B "$work/consumer-build" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
  -DREADME_EXAMPLE="$readme_example" >"$work/consumer-configure.log" 2>&1 ||
  { cat "$work/consumer-configure.log" >&2; fail "the consumer project does not configure"; }
found_dir=$(sed -n 's/^manyworlds_DIR:PATH=//p' "$work/consumer-build/CMakeCache.txt")
[ "$found_dir" = "$cmake_dir" ] || fail "find_package found manyworlds in '$found_dir', not $cmake_dir"
"$cmake" --build "$work/consumer-build" --parallel 1 >"$work/consumer-build.log" 2>&1 ||
  { cat "$work/consumer-build.log" >&2; fail "the consumer project or the README example does not build"; }
# Only the prefix: no include path into this source tree.
while read -r dir; do
  case $dir in
    "$prefix"/*) ;;
    "$source_dir" | "$source_dir"/*) fail "the consumer's compile commands use -I $dir" ;;
  esac
done < <(grep -o -E -e '-I[^ "]+' -e '-isystem [^ "]+' "$work/consumer-build/compile_commands.json" |
         sed -E 's/^-I|^-isystem //')
grep -q -e '-std=c++20' -e '-std=gnu++20' "$work/consumer-build/compile_commands.json" ||
  fail "manyworlds::manyworlds did not bring C++20 to the consumer"
"$work/consumer-build/consumer" || fail "the consumer (CMake) failed"

# ---- (d, second half) run the README example
step "running the README example"
"$work/consumer-build/readme_example" || fail "the README example failed"

# ---- (c) pkg-config and plain c++
step "building the consumer with $cxx and pkg-config"
export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
pc_version=$("$pkg_config" --modversion manyworlds) || fail "pkg-config does not find manyworlds"
[ "$pc_version" = "$version" ] || fail "manyworlds.pc says version $pc_version, not $version"
read -r -a pc_cflags < <("$pkg_config" --cflags manyworlds)
read -r -a pc_libs < <("$pkg_config" --libs manyworlds)
"$cxx" "${pc_cflags[@]}" -Wall -Wextra -Wpedantic -Werror \
  "$source_dir/tests/package/consumer/consumer.cc" "${pc_libs[@]}" -o "$work/consumer-pc" ||
  fail "the consumer does not build with: $cxx ${pc_cflags[*]} consumer.cc ${pc_libs[*]}"
"$work/consumer-pc" || fail "the consumer (pkg-config) failed"

# ---- (e) the MPI layer from an outside project, under mpirun
if [ -n "$mpiexec" ]; then
  step "running the consumer's ShardedBatch program with 2 MPI ranks"
  [ -x "$work/consumer-build/mpi_consumer" ] ||
    fail "find_package(manyworlds) gave no manyworlds::mpi: the consumer's mpi_consumer was not built"
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    "$mpiexec" -n 2 --oversubscribe "$work/consumer-build/mpi_consumer" ||
    fail "the consumer's ShardedBatch program failed under $mpiexec -n 2"
fi

step "passed: installed, find_package and pkg-config consumers and the README example built and ran"
