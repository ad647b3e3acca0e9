#!/usr/bin/env bash
# Builds the benchmark peer of geomint-peer-heyoka from source on Debian 12: mp++ 2.0.0 (with
# MPFR, quadmath/real128, Boost.Serialization and fmt, as heyoka requires) and then heyoka 7.2.1
# (with mp++ and SLEEF, against LLVM 16), both Release, installed into PREFIX. It installs the
# Debian packages it needs (apt-get, only the missing ones) and applies two fixes to the heyoka
# source tree, both idempotent:
#  - the snapshot of heyoka's sources may lack the 54 large VSOP2013 data files
#    src/detail/vsop2013/vsop2013_P_V.cpp; for each missing one it writes a stand-in that defines
#    the data-pointer array declared in include/heyoka/detail/vsop2013/vsop2013_P.hpp (all null),
#    so that libheyoka links. The VSOP2013 model is then unusable; the benchmark does not use it.
#  - Boost 1.74's boost/serialization/unordered_set.hpp uses library_version_type without
#    including its header; src/callback/angle_reducer.cpp gets that include in front of it.
# Every build step runs under nice -n 19 with -j${JOBS:-2}. Re-running it on built trees is cheap
# (nothing is rebuilt). No LD_LIBRARY_PATH is needed: the installed libraries carry RUNPATH PREFIX/lib.
# usage: tools/bench/peers/build_heyoka.sh MPPP_SOURCE_DIR HEYOKA_SOURCE_DIR PREFIX [BUILD_DIR]
set -euo pipefail
usage() {
  echo "usage: build_heyoka.sh MPPP_SOURCE_DIR HEYOKA_SOURCE_DIR PREFIX [BUILD_DIR (default ./heyoka-build)]" >&2
  exit 2
}
if [ $# -lt 3 ] || [ $# -gt 4 ]; then usage; fi
if [ ! -f "$1/CMakeLists.txt" ] || [ ! -d "$1/include/mp++" ]; then
  echo "build_heyoka.sh: $1 is not an mp++ source tree" >&2
  usage
fi
if [ ! -f "$2/CMakeLists.txt" ] || [ ! -d "$2/include/heyoka" ]; then
  echo "build_heyoka.sh: $2 is not a heyoka source tree" >&2
  usage
fi
mppp_src=$(realpath "$1")
heyoka_src=$(realpath "$2")
mkdir -p "$3" "${4:-heyoka-build}"
prefix=$(realpath "$3")
build=$(realpath "${4:-heyoka-build}")
jobs=${JOBS:-2}

# Debian packages.
pkgs=(cmake g++ llvm-16-dev libboost-dev libboost-serialization-dev libfmt-dev libspdlog-dev
  libtbb-dev libmpfr-dev libgmp-dev libsleef-dev)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=; [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi

# Fix 1: stand-ins for the missing VSOP2013 data files (only those that are missing).
grep -o 'src/detail/vsop2013/vsop2013_[0-9]*_[0-9]*\.cpp' "$heyoka_src/CMakeLists.txt" | while read -r f; do
  [ -e "$heyoka_src/$f" ] && continue
  n=$(basename "$f" .cpp) # vsop2013_P_V
  p=${n#vsop2013_}; p=${p%_*}
  mkdir -p "$(dirname "$heyoka_src/$f")"
  cat > "$heyoka_src/$f" <<EOF
// Stand-in written by geomint's tools/bench/peers/build_heyoka.sh: the source snapshot lacks the
// VSOP2013 data. All series pointers are null; the VSOP2013 model must not be used.
#include <iterator>

#include <heyoka/config.hpp>
#include <heyoka/detail/vsop2013/vsop2013_$p.hpp>

HEYOKA_BEGIN_NAMESPACE

namespace model::detail
{

const double *const ${n}_data[std::size(${n}_sizes)] = {};

} // namespace model::detail

HEYOKA_END_NAMESPACE
EOF
  echo "build_heyoka.sh: wrote the stand-in $f"
done

# Fix 2: Boost 1.74's serialization/unordered_set.hpp needs library_version_type.hpp first.
ar=$heyoka_src/src/callback/angle_reducer.cpp
if ! grep -q 'boost/serialization/library_version_type.hpp' "$ar"; then
  sed -i 's|^#include <boost/serialization/unordered_set.hpp>|#include <boost/serialization/library_version_type.hpp>\n&|' "$ar"
  grep -q 'boost/serialization/library_version_type.hpp' "$ar" || { echo "build_heyoka.sh: could not patch $ar" >&2; exit 1; }
fi

# mp++, then heyoka.
common=(-DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_INSTALL_LIBDIR=lib
  -DCMAKE_INSTALL_RPATH="$prefix/lib" -DCMAKE_PREFIX_PATH="$prefix")
nice -n 19 cmake -S "$mppp_src" -B "$build/mppp" "${common[@]}" -DMPPP_WITH_MPFR=ON \
  -DMPPP_WITH_QUADMATH=ON -DMPPP_WITH_BOOST_S11N=ON -DMPPP_WITH_FMT=ON -DMPPP_BUILD_TESTS=OFF
nice -n 19 cmake --build "$build/mppp" -j"$jobs"
nice -n 19 cmake --install "$build/mppp"
nice -n 19 cmake -S "$heyoka_src" -B "$build/heyoka" "${common[@]}" \
  -DLLVM_DIR=/usr/lib/llvm-16/lib/cmake/llvm -DHEYOKA_WITH_MPPP=ON -DHEYOKA_WITH_SLEEF=ON \
  -DHEYOKA_BUILD_TESTS=OFF
nice -n 19 cmake --build "$build/heyoka" -j"$jobs"
nice -n 19 cmake --install "$build/heyoka"

echo "build_heyoka.sh: mp++ and heyoka are installed in $prefix; configure geomint with"
echo "  -DGEOMINT_PEER_HEYOKA=ON -DCMAKE_PREFIX_PATH=$prefix"
echo "(libheyoka and libmp++ carry the RUNPATH $prefix/lib and CMake gives geomint-peer-heyoka the"
echo " same, so no LD_LIBRARY_PATH is needed; a program linked otherwise needs"
echo " LD_LIBRARY_PATH=$prefix/lib)"
