#pragma once
// The OpenGL format of Facet's windows: 4.1 core (what macOS and every driver since 2010 give;
// render/ asks for nothing newer without checking GLInfo).

#include <QSurfaceFormat>

namespace facet {

QSurfaceFormat viewportSurfaceFormat();

// Makes viewportSurfaceFormat() the default and lets GL widgets share resources (cached IBL maps
// and textures outlive a widget that is re-parented or torn off). Call before QApplication exists.
void installViewportSurfaceFormat();

} // namespace facet
