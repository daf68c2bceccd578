#include "ui/ViewportWidget.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

namespace facet {

ViewportWidget::ViewportWidget(QWidget* parent)
    : QOpenGLWidget(parent)
{
    setObjectName(QStringLiteral("viewport"));
    setMinimumSize(160, 120);
}

QSize ViewportWidget::sizeHint() const
{
    return {960, 640};
}

void ViewportWidget::initializeGL()
{
    // render/ resolves GL through libepoxy for whichever context is current, Qt's included.
    m_glInfo = queryCurrentGLInfo();
    m_glProblem.clear();
    if (!m_glInfo.isValid())
        m_glProblem = tr("no OpenGL context");
    else if (!m_glInfo.atLeast(4, 1) || !m_glInfo.coreProfile)
        m_glProblem = m_glInfo.coreProfile ? tr("Facet needs OpenGL 4.1 core")
                                           : tr("Facet needs OpenGL 4.1 core, not a compatibility profile");
    Q_EMIT glInitialized();
}

void ViewportWidget::paintGL()
{
    QOpenGLFunctions* gl = context()->functions();
    gl->glClearColor(kClearGrey, kClearGrey, kClearGrey, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

} // namespace facet
