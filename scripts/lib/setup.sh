# Shared by scripts/demo and scripts/test: install missing Debian packages, build.
# Sourced, not executed. Idempotent: a second run installs nothing and rebuilds incrementally.

CT_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
CT_BUILD=${CLOTHTRACK_BUILD_DIR:-$CT_ROOT/build}
CT_PYTHON=/usr/bin/python3

# Everything the build, the tests and the plugin need, all from Debian 12.
CT_PACKAGES="cmake ninja-build g++ pkg-config libeigen3-dev libflann-dev liblz4-dev libvtk9-dev python3-vtk9
  python3-numpy python3-matplotlib libpcl-dev libboost-program-options-dev libgtest-dev paraview paraview-dev libqt5svg5-dev
  qtxmlpatterns5-dev-tools xvfb xauth dpkg-dev nlohmann-json3-dev libsuitesparse-dev openmpi-bin"

ct_log() { printf '[clothtrack] %s\n' "$*" >&2; }
ct_die() { printf '[clothtrack] error: %s\n' "$*" >&2; exit 1; }

ct_install_dependencies() { ct_install_packages $CT_PACKAGES; }

# Installs those of the given Debian packages that are missing.
ct_install_packages() {
  local missing=() pkg
  for pkg in "$@"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  ct_log "installing ${#missing[@]} Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || ct_die "missing packages (${missing[*]}) and not root: install them or run as root"
    sudo=sudo
  fi
  $sudo apt-get update -qq || ct_die "apt-get update failed"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
    || ct_die "apt-get install failed for: ${missing[*]}"
}

# Configures (first time) and builds everything, including the ParaView plugin.
ct_build() {
  local pv_dir
  pv_dir=$("$CT_PYTHON" "$CT_ROOT/scripts/lib/paraview_prefix.py" "$CT_BUILD/_paraview") \
    || ct_die "could not prepare the ParaView prefix for the plugin build"
  if [ ! -f "$CT_BUILD/build.ninja" ]; then
    ct_log "configuring in $CT_BUILD"
    cmake -S "$CT_ROOT" -B "$CT_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DPython3_EXECUTABLE="$CT_PYTHON" \
      -DCLOTHTRACK_BUILD_PARAVIEW_PLUGIN=ON -DClothTrack_ParaView_DIR="$pv_dir" \
      -DClothTrack_PVPYTHON="$CT_BUILD/_paraview/python3-paraview/usr/bin/pvpython" >"$CT_BUILD.configure.log" 2>&1 \
      || { cat "$CT_BUILD.configure.log" >&2; ct_die "cmake configuration failed"; }
  fi
  ct_log "building (ninja, $(nproc) jobs)"
  cmake --build "$CT_BUILD" -- -j"$(nproc)" || ct_die "build failed"
}
