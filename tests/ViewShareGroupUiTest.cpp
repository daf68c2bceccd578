// ui/viewport/ViewShareGroup: the views of the window share one IBL precompute and one texture cache when
// their contexts share (Facet sets Qt::AA_ShareOpenGLContexts, so two windows' views share too);
// the resources live while a view holds them and are made anew once every view has gone; a
// context of another share group gets resources of its own (its GL names mean nothing there).

#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewShareGroup.h"
#include "ui/viewport/ViewportWidget.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QVBoxLayout>
#include <QWidget>
#include <QtTest/QTest>

#include <memory>

using namespace facet;

class ViewShareGroupUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { installViewportSurfaceFormat(); }

private Q_SLOTS:
    void viewsShareOneSetOfResources_data();
    void viewsShareOneSetOfResources();
    void contextOfAnotherShareGroupGetsItsOwn();
};

void ViewShareGroupUiTest::viewsShareOneSetOfResources_data()
{
    QTest::addColumn<bool>("sameWindow");
    QTest::newRow("two views of one window") << true;
    QTest::newRow("views of two windows") << false;
}

void ViewShareGroupUiTest::viewsShareOneSetOfResources()
{
    QFETCH(bool, sameWindow);
    auto group = std::make_shared<ViewShareGroup>(/*useDiskCache=*/false);
    auto first = std::make_unique<QWidget>();
    auto second = sameWindow ? nullptr : std::make_unique<QWidget>();
    auto* a = new ViewportWidget;
    auto* b = new ViewportWidget;
    auto* firstLayout = new QVBoxLayout(first.get());
    firstLayout->addWidget(a);
    if (sameWindow)
        firstLayout->addWidget(b);
    else
        (new QVBoxLayout(second.get()))->addWidget(b);
    a->setShareGroup(group);
    b->setShareGroup(group);
    for (QWidget* window : {first.get(), second.get()}) {
        if (!window)
            continue;
        window->resize(320, 240);
        window->show();
        QVERIFY(QTest::qWaitForWindowExposed(window));
    }
    QTRY_VERIFY(a->context() && b->context() && a->glInfo().isValid() && b->glInfo().isValid());
    QVERIFY(QOpenGLContext::areSharing(a->context(), b->context()));
    QCOMPARE(group->resourcesMade(), 1);

    // Every view gone: the resources went with the last one; the next view makes new ones.
    first.reset();
    second.reset();
    QWidget third;
    auto* c = new ViewportWidget;
    (new QVBoxLayout(&third))->addWidget(c);
    c->setShareGroup(group);
    third.resize(320, 240);
    third.show();
    QVERIFY(QTest::qWaitForWindowExposed(&third));
    QTRY_VERIFY(c->context() && c->glInfo().isValid());
    QCOMPARE(group->resourcesMade(), 2);
}

void ViewShareGroupUiTest::contextOfAnotherShareGroupGetsItsOwn()
{
    ViewShareGroup group(/*useDiskCache=*/false);
    QOffscreenSurface surface;
    surface.create();
    QOpenGLContext lone; // plain contexts share with nothing (only widgets get the global one)
    QVERIFY(lone.create());
    QVERIFY(lone.makeCurrent(&surface));
    const ViewShareGroup::Resources made = group.acquire();
    QVERIFY(!made.shared);
    const ViewShareGroup::Resources again = group.acquire(); // the same context
    QVERIFY(again.shared);
    QCOMPARE(again.precompute, made.precompute);
    QCOMPARE(again.textures, made.textures);
    QOpenGLContext other;
    QVERIFY(other.create());
    QVERIFY(other.makeCurrent(&surface));
    QVERIFY(!QOpenGLContext::areSharing(&lone, &other));
    const ViewShareGroup::Resources third = group.acquire();
    QVERIFY(!third.shared);
    QVERIFY(third.precompute != made.precompute && third.textures != made.textures);
    QCOMPARE(group.resourcesMade(), 2);
    // (Nothing was drawn: the resources hold no GL objects yet, whichever context is current.)
    other.doneCurrent();
}

QTEST_MAIN(ViewShareGroupUiTest)
#include "ViewShareGroupUiTest.moc"
