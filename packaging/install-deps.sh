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
  # maths, meshes, images, colour
  libglm-dev libassimp-dev libtinygltf-dev nlohmann-json3-dev libdraco-dev libopenimageio-dev openimageio-tools libopencolorio-dev opencolorio-tools
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
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" </dev/null
