#include "ui/viewport/SurfaceFormat.h"

#include <QCoreApplication>

namespace facet {

QSurfaceFormat viewportSurfaceFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    return format;
}

void installViewportSurfaceFormat()
{
    Q_ASSERT_X(!QCoreApplication::instance(), "installViewportSurfaceFormat",
        "must run before the QApplication is constructed");
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat::setDefaultFormat(viewportSurfaceFormat());
}

} // namespace facet
