#!/usr/bin/env bash
# Fetches Facet's free CC0 sample data (HDR environments, meshes, tileable normal maps) from the
# npm package @pmndrs/assets and decodes it into plain files:
#   DEST/hdri/*.exr   DEST/models/*.glb   DEST/normals/*.webp
# DEST is the first argument, else $FACET_ASSETS_DIR, else ~/.local/share/facet/assets (where the
# app's environment library and the tests look). Idempotent: a stamp file records what is there.
set -euo pipefail

version=1.7.0
dest=${1:-${FACET_ASSETS_DIR:-${XDG_DATA_HOME:-$HOME/.local/share}/facet/assets}}
stamp="$dest/.pmndrs-assets-$version"

if [ -f "$stamp" ]; then
  echo "fetch-assets: sample data present in $dest"
  exit 0
fi
command -v npm >/dev/null || { echo "fetch-assets: npm is needed (packaging/install-deps.sh installs it)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "fetch-assets: downloading @pmndrs/assets@$version"
(cd "$work" && npm pack --silent "@pmndrs/assets@$version" >/dev/null 2>&1) \
  || { echo "fetch-assets: 'npm pack @pmndrs/assets@$version' failed (no network?)" >&2; exit 1; }
tar -xzf "$work"/pmndrs-assets-$version.tgz -C "$work"

# Each asset is a JS module: export default 'data:<mime>;base64,<payload>'
decode() { # src.js dst
  sed -e "s/^export default '[^,]*,//" -e "s/'[;[:space:]]*\$//" "$1" | tr -d '\n' | base64 -d >"$2.tmp"
  mv "$2.tmp" "$2"
}
count=0
for kind in hdri models normals; do
  mkdir -p "$dest/$kind"
  for js in "$work"/package/$kind/*.js; do
    name=$(basename "$js" .js)
    decode "$js" "$dest/$kind/$name"
    count=$((count + 1))
  done
done
cp "$work/package/LICENSE" "$dest/LICENSE" 2>/dev/null || true
touch "$stamp"
echo "fetch-assets: decoded $count files into $dest"
