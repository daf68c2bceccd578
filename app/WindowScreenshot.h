#pragma once
// `facet --screenshot FILE.png`: once the central area has drawn its first complete frame (the
// single viewport: full resolution, every map loaded and on the GPU, not a preview drawn while a
// texture set loads; a Compare mode, when the project opened in one: every cell drawn at full
// resolution with its environment loaded), saves a grab of the whole window and quits (exit code
// 0 when saved, 1 when not). For README pictures and smoke tests.

#include <QObject>
#include <QString>
#include <QTimer>

class QWidget;

namespace facet {

class CompareView;
class ViewportWidget;

class WindowScreenshot : public QObject {
    Q_OBJECT
public:
    // How long to wait for the first complete frame before giving up (a context that never comes
    // up); a refining view's frames (fis, reference) restart the wait.
    static constexpr int kFirstFrameTimeoutMs = 60000;

    WindowScreenshot(QWidget* window, ViewportWidget* viewport, CompareView* compare, QString path,
        QObject* parent = nullptr);

    // Whether Qt can write an image of `path`'s suffix; if not, `why` says so. Needs a QGuiApplication
    // (image-format plugins), so main() checks this before it shows the window.
    static bool canWriteFormatOf(const QString& path, QString* why);

private:
    void save();
    void fail(const QString& why);

    QWidget* m_window;
    QString m_path;
    QString m_refinement; // " (refined by fis, 1024 samples)" when the project refines, else empty
    QTimer m_timeout;
    bool m_done = false;
};

} // namespace facet
