#pragma once
// The main window the material UI tests drive (MaterialsUiTest, MaterialsFrameUiTest,
// AuthoringUiTest, MaterialTransferUiTest), a base of each test class: the small assets written by the test
// (support/TestAssets.h: two quads side by side, "Left" in the material "Red" and "Right" in "Blue", and the
// same with the right part's alpha 0.3), the window shown with its first frame drawn, and opening a file
// until its assets arrived. Links facet_ui: compiled into those tests only.

#include "ui/MainWindow.h"
#include "ui/document/Document.h"
#include "ui/viewport/ViewportWidget.h"

#include "WindowTestSupport.h"

#include <QString>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <memory>

namespace facet::test {

class TwoMaterialWindowFixture {
protected:
    // The test case's set-up (its initTestCase: it fails the test case when the window did not
    // show) and tear-down (its cleanupTestCase).
    void initWindowFixture();
    void cleanupWindowFixture();

    // Opens `path` and waits until its mesh (and environment) arrived: files load off the GUI
    // thread (ui/document/DocumentAssets).
    bool open(const QString& path);
    // Opens the two-material asset, settled, with an empty undo stack (WindowTestSupport.h
    // openAndSettle): true when it shows its two parts.
    bool openTwoMaterials();
    // Raises the dock that holds `widget` and gives it the focus (WindowTestSupport.h focusWidget).
    static bool focus(QWidget* widget) { return focusWidget(widget); }

    QTemporaryDir m_dir;
    QTemporaryDir m_recovery;
    QString m_twoMaterials; // support/TestAssets writeTwoMaterialAsset
    QString m_translucent; // the same with the right part's alpha 0.3
    std::unique_ptr<MainWindow> m_window;
    Document* m_document = nullptr;
    ViewportWidget* m_viewport = nullptr;
};

} // namespace facet::test
