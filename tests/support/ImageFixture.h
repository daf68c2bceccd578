#pragma once
// The fixture files of core/image/Image's tests (ImageTest, ImageLoadErrorsTest), written with
// OpenImageIO directly (not through Image::save) so a bug in save cannot hide one in load.
// Compiled into those tests only.

#include <QString>

#include <OpenImageIO/typedesc.h>

#include <vector>

namespace facet::test {

// Writes `values` (interleaved, `channels` per pixel) as a file of `fileType`, exactly: integer
// formats get unassociated alpha so the colour bytes are the ones given.
bool writeFixture(const QString& path, int width, int height, int channels, OIIO::TypeDesc fileType,
    const std::vector<float>& values, const char* colorSpace = nullptr);

} // namespace facet::test
