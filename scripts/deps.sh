# Sourced by the quick-start scripts: installs the Debian packages that are missing.
# Usage: geomint_install_deps pkg...
geomint_install_deps() {
  local missing=()
  for pkg in "$@"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "geomint: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}
GEOMINT_BUILD_PACKAGES=(cmake make g++ clang libeigen3-dev libboost-dev catch2 libmpfr-dev libgmp-dev libqd-dev libsleef-dev doxygen)
