#pragma once
// Facet's main window. It wires: menus, the central viewport, the status bar. Panels and their
// controllers get their own classes and are only connected here.

#include <QMainWindow>

class QLabel;

namespace facet {

class ViewportWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    ViewportWidget* viewport() const { return m_viewport; }
    // Shows a message in the status bar until the next one (e.g. a warning from the command line).
    void showStatusMessage(const QString& message);
    // The About box's text: version, Qt, and the viewport's OpenGL (once initialised).
    QString aboutText() const;

private:
    void createMenus();
    void showAbout();
    void onViewportGLInitialized();

    ViewportWidget* m_viewport = nullptr;
    QLabel* m_glStatusLabel = nullptr;
};

} // namespace facet
