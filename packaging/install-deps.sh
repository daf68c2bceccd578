#!/usr/bin/env bash
# Installs everything Facet needs to build, run and test on Debian 12 (bookworm).
# Non-interactive and idempotent: packages already present are left alone, and apt is only
# asked when something is missing. Run as root, or as a user with sudo.
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config git
  # Qt 6 (Widgets, OpenGL widgets, Test); the xcb platform plugin for the GUI
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-qpa-plugins libxkbcommon-dev
  # maths, meshes, images, colour; ray tracing for the ground truth of staged scenes (Embree 3)
  libembree-dev libglm-dev libassimp-dev libtinygltf-dev nlohmann-json3-dev libdraco-dev libopenimageio-dev openimageio-tools libopenexr-dev libpng-dev libopencolorio-dev opencolorio-tools
  # OpenGL: loader, Mesa's software rasteriser, EGL for headless rendering
  libepoxy-dev libgl1-mesa-dri libegl-mesa0 libegl-dev mesa-utils
  # headless GUI tests
  xvfb xauth
  # the font of the window and of facet sheet's labels (Qt's offscreen platform draws with it)
  fonts-dejavu-core
  # fetching the CC0 test environments and meshes (npm registry)
  npm ca-certificates
)

missing=()
for p in "${packages[@]}"; do
  # npm may come from another source (e.g. a Node.js install): the command is what matters.
  if [ "$p" = npm ] && command -v npm >/dev/null 2>&1; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
fi

# The Khronos glTF-Validator (npm), which the tests run on every glTF asset facet export writes
# (tests/tools/validate-gltf.cjs). Into the user's data folder, no root needed; $FACET_TOOLS_DIR
# overrides (CMake's FACET_TOOLS_DIR must then say the same).
validator_version=2.0.0-dev.3.10
tools=${FACET_TOOLS_DIR:-${XDG_DATA_HOME:-$HOME/.local/share}/facet/tools}
if grep -q "\"version\": \"$validator_version\"" "$tools/node_modules/gltf-validator/package.json" 2>/dev/null; then
  echo "install-deps: gltf-validator $validator_version present in $tools"
else
  echo "install-deps: installing gltf-validator $validator_version into $tools"
  mkdir -p "$tools"
  npm install --silent --no-audit --no-fund --prefix "$tools" "gltf-validator@$validator_version" >/dev/null \
    || echo "install-deps: warning: 'npm install gltf-validator@$validator_version' failed (no network?);" \
      "Facet builds and runs without it, the glTF export tests need it" >&2
fi
