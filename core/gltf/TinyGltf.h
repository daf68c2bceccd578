#pragma once
// Private to core/: tinygltf (Debian's libtinygltf-dev header) compiled into facet_core under a
// namespace of Facet's own. Not the packaged libtinygltf.so: Assimp 5.2 links libdraco, which
// exports its own, older copy of tinygltf's symbols, and the dynamic linker bound Facet's calls
// to that copy (a different class layout: "free(): invalid pointer" on the first load). With the
// namespace renamed nothing can bind across. Images are never decoded by tinygltf (no stb_image;
// core/image/Image reads them through OpenImageIO) and external images are not read at all.
#define tinygltf facet_tinygltf
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
