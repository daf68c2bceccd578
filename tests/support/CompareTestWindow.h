#pragma once
// The main window the Compare UI tests drive (CompareUiTest, CompareWindowUiTest): made and shown
// at 1100 x 760 with the IBL results in memory only (precomputes are counted, the user's cache is
// never touched), a project set through one undo step, and the wait for the Compare view's first
// settled frame (every cell drawn in full, nothing loading, no preview). Links facet_ui: compiled
// into those tests only.

#include "core/project/Project.h"

#include <QString>

#include <memory>

namespace facet {
class CompareController;
class CompareView;
class Document;
class MainWindow;
} // namespace facet

namespace facet::test {

class CompareTestWindow {
public:
    CompareTestWindow();
    ~CompareTestWindow();

    // Makes and shows the window; false if it was not exposed.
    bool open(const QString& recoveryDirectory);
    void close();

    // The default project at draft IBL quality without MSAA (short llvmpipe precomputes), the
    // camera the reference view's, and its default compare layout.
    static Project baseProject();
    // Sets `project` through one undo step (and its camera) and waits for a settled frame.
    bool setProject(const Project& project);
    // True at once while the single view is shown; otherwise waits until the Compare view drew
    // a frame with every cell in full, nothing loading and the error view's reference done.
    bool waitForSettledFrame(int timeoutMs = 60000);

    MainWindow* window() const { return m_window.get(); }
    Document* document() const { return m_document; }
    CompareView* view() const { return m_view; }
    CompareController* controller() const { return m_controller; }

private:
    std::unique_ptr<MainWindow> m_window;
    Document* m_document = nullptr;
    CompareView* m_view = nullptr;
    CompareController* m_controller = nullptr;
};

} // namespace facet::test
