#pragma once
// The 3D view. It presents frames and nothing else: the renderer (render/) draws a snapshot of
// the document into its own framebuffer, and this widget shows it. Until the renderer lands it
// shows the empty viewport, a flat dark grey.

#include "render/GLInfo.h"

#include <QOpenGLWidget>
#include <QString>

namespace facet {

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    // The empty viewport's colour, the same in R, G and B (46/255 once in an 8-bit window).
    static constexpr float kClearGrey = 0.18f;

    explicit ViewportWidget(QWidget* parent = nullptr);

    // What the widget's context is; valid once glInitialized() was emitted.
    const GLInfo& glInfo() const { return m_glInfo; }
    // Why the context is not good enough for Facet (below 4.1 core); empty when it is.
    const QString& glProblem() const { return m_glProblem; }

    QSize sizeHint() const override;

Q_SIGNALS:
    // The context exists and glInfo() describes it (emitted from initializeGL, context current).
    void glInitialized();

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    // Seam for the renderer: a later setFrameSource(...) gives this widget an object that renders
    // the current document snapshot into a render/Framebuffer on request; paintGL() then only
    // blits that framebuffer into defaultFramebufferObject(). Rendering stays on demand: the
    // widget calls update() when the document changes, never on a timer.
    GLInfo m_glInfo;
    QString m_glProblem;
};

} // namespace facet
