#include "ui/MainWindow.h"

#include "core/material/MaterialPresets.h"
#include "core/support/AtomicFile.h"
#include "ui/compare/CompareActions.h"
#include "ui/compare/CompareController.h"
#include "ui/compare/CompareView.h"
#include "ui/dialogs/ExportDialog.h"
#include "ui/dialogs/ImageSaver.h"
#include "ui/dialogs/PreferencesDialog.h"
#include "ui/docks/DockScrollArea.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/docks/LightsDock.h"
#include "ui/docks/MaterialDock.h"
#include "ui/docks/MaterialsDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/docks/ValuesDock.h"
#include "ui/docks/ViewDock.h"
#include "ui/document/AutosaveController.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentAssets.h"
#include "ui/document/MaterialTransfer.h"
#include "ui/document/ProjectFileController.h"
#include "ui/document/UndoShortcutRouter.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/MapLoadStatus.h"
#include "ui/viewport/PartPicker.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ValuePicker.h"
#include "ui/viewport/ViewShareGroup.h"
#include "ui/viewport/ViewStatus.h"
#include "ui/viewport/ViewportDropHandler.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/FreedMemoryTimer.h"
#include "ui/widgets/ProblemBar.h"
#include "ui/widgets/WindowMessages.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QBuffer>
#include <QClipboard>
#include <QCloseEvent>
#include <QDebug>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonDocument>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>

#include <initializer_list>

namespace facet {

namespace {

const QLatin1String kGeometryKey("window/geometry");
const QLatin1String kLayoutKey("window/layout");
// 2: the Materials dock. 3: every dock in one column on the right (the view was left 446 of 1200
// pixels by docks on both sides). A saved layout of another version is not restored: the default
// shows, once, and the next close saves it under this version.
constexpr int kLayoutVersion = 3;
// The default dock column: a quarter of the window's width; the Materials dock takes this share of
// the column's height, the tabs below the rest.
constexpr int kDockColumnWidthDivisor = 4;
constexpr double kMaterialsHeightShare = 0.35;
constexpr int kPresetShortcuts = 9; // Ctrl+1..9

} // namespace

MainWindow::MainWindow(QWidget* parent, const QString& recoveryDirectory)
    : QMainWindow(parent)
    , m_document(new Document(this))
    , m_assets(new DocumentAssets(this))
    , m_scene(new SceneController(m_document, m_assets, this))
    , m_viewport(new ViewportWidget(this))
    , m_camera(new CameraController(m_document, m_scene, m_viewport, this))
    , m_files(new ProjectFileController(m_document, this, this))
    // After the camera: the picker's filter must see presses and releases before the camera's.
    , m_picker(new PartPicker(m_document, m_scene, m_viewport, this))
    , m_valuePicker(new ValuePicker(m_document, m_scene, m_viewport, m_picker, this))
    , m_drops(new ViewportDropHandler(m_files, m_viewport, this))
    , m_autosave(new AutosaveController(m_document, recoveryDirectory, this))
    , m_compareController(new CompareController(m_document, this))
    , m_glStatusLabel(new QLabel(tr("Initialising OpenGL…"), this))
    , m_frameStatsLabel(new QLabel(this))
{
    // The central area: the single view, or the Compare view of the project's compare mode.
    auto* central = new QStackedWidget(this);
    central->addWidget(m_viewport);
    central->addWidget(m_compareView = new CompareView(m_document, m_scene, m_compareController, central));
    setCentralWidget(central);
    m_imageSaver = new ImageSaver(this, m_document, m_viewport, m_compareView,
        [central, this] { return central->currentWidget() == m_compareView; });
    // One IBL precompute and one texture cache for both views (their contexts share).
    auto shareGroup = std::make_shared<ViewShareGroup>();
    m_viewport->setShareGroup(shareGroup);
    m_compareView->setShareGroup(shareGroup);
    m_viewport->setSceneController(m_scene);
    setDockOptions(AnimatedDocks | AllowNestedDocks | AllowTabbedDocks);
    m_glStatusLabel->setObjectName(QStringLiteral("glStatusLabel"));
    m_frameStatsLabel->setObjectName(QStringLiteral("frameStatsLabel"));
    statusBar()->addPermanentWidget(new MapLoadStatus(m_scene, this)); // maps decoding off the GUI thread
    statusBar()->addPermanentWidget(m_frameStatsLabel);
    statusBar()->addPermanentWidget(m_glStatusLabel);
    createMenus();
    createDocks();
    m_compareActions = new CompareActions(m_document, m_compareController, central, this);
    menuBar()->insertMenu(m_helpMenuAction, m_compareActions->menu());
    addToolBar(Qt::TopToolBarArea, m_compareActions->toolBar());
    m_compareView->setEnvironmentChoices(
        [this] { return CompareActions::choicesOf(m_environmentDock->library()); });

    connect(m_viewport, &ViewportWidget::glInitialized, this, &MainWindow::onViewportGLInitialized);
    // Lighting progress and frame statistics of whichever view the central area shows.
    m_viewStatus = new ViewStatus(
        statusBar(), m_frameStatsLabel, central, m_viewport, m_scene, m_compareView, m_environmentDock, this);
    m_compareActions->setEnvironmentDock(m_environmentDock);
    connect(m_compareActions, &CompareActions::message, m_viewStatus, &ViewStatus::showCompareNote);
    connect(m_scene, &SceneController::message, this, &MainWindow::showStatusMessage);
    connect(m_document, &Document::editRejected, this, &MainWindow::showStatusMessage);
    // What opening, importing or saving a file did ("Opened barrel.glb (3 materials, 5 parts) …")
    // stays a while: the lighting it starts is news the Environment dock also shows (issue 30).
    connect(m_files, &ProjectFileController::statusMessage, this, [this](const QString& text) {
        showStatusMessage(text);
        m_viewStatus->noteUserMessage();
    });
    connect(m_files, &ProjectFileController::errorReported, this, &MainWindow::showStatusMessage);
    connect(m_imageSaver, &ImageSaver::statusMessage, this, &MainWindow::showStatusMessage);
    connect(m_autosave, &AutosaveController::failed, this, &MainWindow::showStatusMessage);
    createProblemBar();
    m_freedMemory = new FreedMemoryTimer(this);
    m_materialDrops = new MaterialDropHandler(m_document, m_picker, m_viewport, this);
    connect(m_materialDrops, &MaterialDropHandler::message, this, &MainWindow::showStatusMessage);
    connect(m_document, &Document::modifiedChanged, this, &QWidget::setWindowModified);
    connect(m_document, &Document::filePathChanged, this, &MainWindow::updateTitle);
    // An asset opened as an untitled project keeps an empty path but is named in the title.
    connect(m_document, &Document::projectReplaced, this, &MainWindow::updateTitle);
    connect(m_picker, &PartPicker::message, this, &MainWindow::showStatusMessage);
    connect(m_document, &Document::missingFilesChanged, this, [this](const QStringList& missing) {
        m_relinkAction->setEnabled(!missing.isEmpty());
        // "… missing; use File > Relink Missing Files" stayed after the files were found (issue 30).
        if (missing.isEmpty() && statusMessage().contains(tr("Relink Missing Files")))
            showStatusMessage(tr("Every file the project names is found"));
    });
    updateTitle();
    // 1200 x 800, or what the screen has room for (a 1280 x 720 screen cut the window's bottom).
    QSize size(1200, 800);
    if (const QScreen* screen = QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableGeometry().size() * 0.95);
    resize(size);
}

MainWindow::~MainWindow() = default;

void MainWindow::createMenus()
{
    createFileMenu();
    createEditMenu();
    // Ctrl+Z / Ctrl+Shift+Z reach the document from a focused field once its edit is committed.
    qApp->installEventFilter(new UndoShortcutRouter(this));
    createViewMenu();

    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    m_helpMenuAction = helpMenu->menuAction();
    helpMenu->setObjectName(QStringLiteral("helpMenu"));
    QAction* aboutAction = helpMenu->addAction(tr("&About Facet"), this, &MainWindow::showAbout);
    aboutAction->setObjectName(QStringLiteral("aboutAction"));
    aboutAction->setMenuRole(QAction::AboutRole);
    QAction* aboutQtAction = helpMenu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    aboutQtAction->setMenuRole(QAction::AboutQtRole);
}

void MainWindow::createFileMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&File"));
    menu->setObjectName(QStringLiteral("fileMenu"));
    const auto add = [this, menu](const QString& text, const char* name, QKeySequence keys, auto slot) {
        QAction* action = menu->addAction(text, m_files, slot);
        action->setObjectName(QLatin1String(name));
        action->setShortcut(keys);
        return action;
    };
    add(tr("&New"), "newAction", QKeySequence::New, &ProjectFileController::newProject);
    add(tr("&Open…"), "openAction", QKeySequence::Open, &ProjectFileController::open);
    m_recentMenu = menu->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    connect(m_files, &ProjectFileController::recentFilesChanged, this, &MainWindow::updateRecentFilesMenu);
    updateRecentFilesMenu();
    add(tr("&Import Asset…"), "importAssetAction", QKeySequence(Qt::CTRL | Qt::Key_I),
        &ProjectFileController::importAsset);
    menu->addSeparator();
    add(tr("&Save"), "saveAction", QKeySequence::Save, &ProjectFileController::save);
    add(tr("Save &As…"), "saveAsAction", QKeySequence::SaveAs, &ProjectFileController::saveAs);
    QAction* reloadAction
        = add(tr("Re&load From Disk"), "reloadAction", QKeySequence(), &ProjectFileController::reload);
    reloadAction->setEnabled(!m_document->filePath().isEmpty());
    connect(m_document, &Document::filePathChanged, reloadAction,
        [reloadAction](const QString& path) { reloadAction->setEnabled(!path.isEmpty()); });
    menu->addSeparator();
    QAction* exportAction = menu->addAction(tr("&Export…"), this, &MainWindow::exportMaterials);
    exportAction->setObjectName(QStringLiteral("exportAction"));
    exportAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    QAction* saveImageAction = menu->addAction(tr("Save &Image…"), this, &MainWindow::saveImage);
    saveImageAction->setObjectName(QStringLiteral("saveImageAction"));
    saveImageAction->setShortcut(QKeySequence(Qt::Key_F12));
    QAction* saveTurntableAction
        = menu->addAction(tr("Save &Turntable…"), m_imageSaver, &ImageSaver::saveTurntable);
    saveTurntableAction->setObjectName(QStringLiteral("saveTurntableAction"));
    saveTurntableAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F12));
    menu->addSeparator();
    m_relinkAction = add(tr("Re&link Missing Files…"), "relinkAction", QKeySequence(),
        &ProjectFileController::showMissingFilesDialog);
    m_relinkAction->setEnabled(false);
    menu->addSeparator();
    QAction* quitAction = menu->addAction(tr("&Quit"), this, &QWidget::close);
    quitAction->setObjectName(QStringLiteral("quitAction"));
    quitAction->setShortcut(QKeySequence::Quit);
    quitAction->setMenuRole(QAction::QuitRole);
}

void MainWindow::createEditMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&Edit"));
    menu->setObjectName(QStringLiteral("editMenu"));
    QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    // What an undone step had said ("Assigned 4 maps") is not left on the bar (issue 30).
    connect(undo, &QAction::triggered, this,
        [this] { showStatusMessage(tr("Undone: %1").arg(m_document->undoStack()->redoText())); });
    connect(redo, &QAction::triggered, this,
        [this] { showStatusMessage(tr("Redone: %1").arg(m_document->undoStack()->undoText())); });
    menu->addAction(undo);
    menu->addAction(redo);
    menu->addSeparator();
    // A material's look and maps from one material (or window) to another (issue 30).
    QAction* copy = menu->addAction(tr("&Copy Material"), this, &MainWindow::copyMaterial);
    copy->setObjectName(QStringLiteral("copyMaterialAction"));
    copy->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_C));
    QAction* paste = menu->addAction(tr("&Paste Material"), this, &MainWindow::pasteMaterial);
    paste->setObjectName(QStringLiteral("pasteMaterialAction"));
    paste->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_V));
    menu->addSeparator();
    QMenu* presets = menu->addMenu(tr("Apply &Preset"));
    presets->setObjectName(QStringLiteral("presetMenu"));
    int index = 0;
    for (const MaterialPreset& preset : builtinPresets()) {
        QAction* action = presets->addAction(QString::fromStdString(preset.displayName));
        action->setObjectName(QStringLiteral("presetAction_%1").arg(QString::fromStdString(preset.id)));
        // Ctrl+1..9: a stray number key must not replace the material's look (issue 30).
        if (index < kPresetShortcuts)
            action->setShortcut(QKeySequence(Qt::CTRL | (Qt::Key_1 + index)));
        connect(action, &QAction::triggered, m_document,
            [this, &preset] { showStatusMessage(m_document->applyPreset(preset)); });
        ++index;
    }
    menu->addSeparator();
    QAction* preferences = menu->addAction(tr("Pre&ferences…"), this, &MainWindow::showPreferences);
    preferences->setObjectName(QStringLiteral("preferencesAction"));
    preferences->setShortcut(QKeySequence::Preferences);
    preferences->setMenuRole(QAction::PreferencesRole);
}

void MainWindow::showPreferences()
{
    const ViewportFrameStats& stats = m_viewport->lastFrameStats();
    PreferencesDialog dialog(stats.iblCacheBytes, stats.iblCacheEntries, this);
    dialog.exec();
}

void MainWindow::createViewMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&View"));
    menu->setObjectName(QStringLiteral("viewMenu"));
    QAction* frame = menu->addAction(tr("&Frame Object"), m_camera, &CameraController::frameObject);
    frame->setObjectName(QStringLiteral("frameAction"));
    frame->setShortcut(Qt::Key_F);
    QAction* reset = menu->addAction(tr("&Reset Camera"), m_camera, &CameraController::resetView);
    reset->setObjectName(QStringLiteral("resetCameraAction"));
    reset->setShortcut(Qt::Key_Home);
    QAction* fly = menu->addAction(tr("F&ly Mode (WASD)"));
    fly->setObjectName(QStringLiteral("flyModeAction"));
    fly->setCheckable(true);
    fly->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F));
    connect(fly, &QAction::toggled, m_camera, &CameraController::setFlyMode);
    connect(m_camera, &CameraController::flyModeChanged, fly, &QAction::setChecked);

    // The mesh's edges over the view (an inspection aid; not saved with the project).
    QAction* wireframe = menu->addAction(tr("&Wireframe"));
    wireframe->setObjectName(QStringLiteral("wireframeAction"));
    wireframe->setCheckable(true);
    wireframe->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_W));
    connect(wireframe, &QAction::toggled, m_viewport, &ViewportWidget::setWireframe);
    // What the view shows under the cursor, and why (the Values dock).
    QAction* values = menu->addAction(tr("&Value Picker"));
    values->setObjectName(QStringLiteral("valuePickerAction"));
    values->setCheckable(true);
    values->setShortcut(Qt::Key_I);
    values->setStatusTip(
        tr("Read the radiance, the screen value and each map's texel under the cursor; click "
           "to pin"));
    connect(values, &QAction::toggled, this, [this](bool on) {
        m_valuePicker->setActive(on);
        if (on) {
            m_valuesDock->show();
            m_valuesDock->raise();
            showStatusMessage(
                tr("Value picker: hover the view, click to pin (Esc follows the cursor again)"));
        }
    });
    connect(m_valuePicker, &ValuePicker::activeChanged, values, &QAction::setChecked);
    connect(m_valuePicker, &ValuePicker::message, this, &MainWindow::showStatusMessage);
    menu->addSeparator();
    QAction* turntable = menu->addAction(tr("&Turntable"));
    turntable->setObjectName(QStringLiteral("turntableAction"));
    turntable->setCheckable(true);
    turntable->setShortcut(Qt::Key_T);
    connect(turntable, &QAction::toggled, m_camera, &CameraController::setTurntableRunning);
    connect(m_camera, &CameraController::turntableRunningChanged, turntable, &QAction::setChecked);
    QMenu* spins = menu->addMenu(tr("Turntable &Spins"));
    auto* group = new QActionGroup(spins);
    const auto addSpin
        = [&](const QString& text, const char* name, CameraController::TurntableTarget target) {
              QAction* action = spins->addAction(text);
              action->setObjectName(QLatin1String(name));
              action->setCheckable(true);
              action->setChecked(m_camera->turntableTarget() == target);
              group->addAction(action);
              connect(action, &QAction::triggered, m_camera,
                  [this, target] { m_camera->setTurntableTarget(target); });
          };
    addSpin(tr("the &Object"), "turntableObjectAction", CameraController::TurntableTarget::Object);
    addSpin(
        tr("the &Environment"), "turntableEnvironmentAction", CameraController::TurntableTarget::Environment);

    menu->addSeparator();
    m_panelsMenu = menu->addMenu(tr("&Panels"));
    m_panelsMenu->setObjectName(QStringLiteral("panelsMenu"));
    QAction* resetLayoutAction = menu->addAction(tr("Reset &Layout"), this, &MainWindow::resetLayout);
    resetLayoutAction->setObjectName(QStringLiteral("resetLayoutAction"));
    QAction* fullScreenAction = menu->addAction(tr("F&ull Screen"));
    fullScreenAction->setObjectName(QStringLiteral("fullScreenAction"));
    fullScreenAction->setCheckable(true);
    fullScreenAction->setShortcut(QKeySequence::FullScreen);
    connect(fullScreenAction, &QAction::toggled, this,
        [this](bool fullScreen) { setWindowState(windowState().setFlag(Qt::WindowFullScreen, fullScreen)); });
}

void MainWindow::createDocks()
{
    // Before show(): the saved layout (QSettings) is restored onto these in showEvent().
    m_materialsDock = new MaterialsDock(m_document, m_scene, this);
    m_textureMapsDock = new TextureMapsDock(m_document, this);
    m_materialDock = new MaterialDock(m_document, this);
    m_environmentDock = new EnvironmentDock(m_document, this);
    m_lightsDock = new LightsDock(m_document, this);
    m_viewDock = new ViewDock(m_document, this);
    // One column on the right, as the properties column of Substance Painter and Marmoset Toolbag:
    // the Materials list on top, because it says what the tabs below edit (Texture Maps, Material)
    // and a click on a part selects in it, so it stays in sight while they are used; the other
    // panels tabbed below it, Texture Maps first. The central view keeps about three quarters of
    // the width (applyDefaultDockSizes), whatever the docks hold.
    addDock(m_materialsDock, Qt::RightDockWidgetArea);
    addDock(m_textureMapsDock, Qt::RightDockWidgetArea);
    splitDockWidget(m_materialsDock, m_textureMapsDock, Qt::Vertical);
    for (QDockWidget* dock :
        std::initializer_list<QDockWidget*> {m_materialDock, m_environmentDock, m_lightsDock, m_viewDock}) {
        addDock(dock, Qt::RightDockWidgetArea);
        tabifyDockWidget(m_textureMapsDock, dock);
    }
    // The Values dock waits, hidden, for View > Value Picker.
    m_valuesDock = new ValuesDock(m_valuePicker, this);
    addDock(m_valuesDock, Qt::RightDockWidgetArea);
    tabifyDockWidget(m_textureMapsDock, m_valuesDock);
    m_valuesDock->hide();
    setTabPosition(Qt::RightDockWidgetArea, QTabWidget::East);
    m_textureMapsDock->raise();
    // Tab names whole (issue 30: at 1280 x 720 they read "Texture M…", "Lig…"): a tab bar too short
    // for them scrolls instead of cutting them. QMainWindow makes its tab bars as docks are tabbed,
    // so each new one is set up once the layout has settled.
    const auto wholeTabNames = [this] {
        QTimer::singleShot(0, this, [this] {
            for (QTabBar* bar : findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
                bar->setElideMode(Qt::ElideNone);
                bar->setUsesScrollButtons(true);
            }
        });
    };
    wholeTabNames();
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        connect(dock, &QDockWidget::dockLocationChanged, this, wholeTabNames);
        connect(dock, &QDockWidget::topLevelChanged, this, wholeTabNames);
    }

    connect(m_textureMapsDock, &TextureMapsDock::message, this, &MainWindow::showStatusMessage);
    connect(m_materialDock, &MaterialDock::message, this, &MainWindow::showStatusMessage);
    connect(m_materialsDock, &MaterialsDock::message, this, &MainWindow::showStatusMessage);
    connect(m_picker, &PartPicker::partPicked, m_materialsDock,
        [this](int part, int, bool extend) { m_materialsDock->selectPart(part, extend); });
    connect(m_environmentDock, &EnvironmentDock::message, this, &MainWindow::showStatusMessage);
    connect(m_lightsDock, &LightsDock::message, this, &MainWindow::showStatusMessage);
    connect(m_viewDock, &ViewDock::message, this, &MainWindow::showStatusMessage);
    connect(m_viewDock, &ViewDock::resetCameraRequested, m_camera, &CameraController::resetView);
    connect(m_viewport, &ViewportWidget::glInitialized, m_viewDock,
        [this] { m_viewDock->showGLInfo(m_viewport->glInfo()); });
    connect(m_viewport, &ViewportWidget::frameRendered, m_viewDock,
        [this] { m_viewDock->showFrameStats(m_viewport->lastFrameStats()); });
}

void MainWindow::updateRecentFilesMenu()
{
    m_recentMenu->clear();
    const QStringList files = m_files->recentFiles();
    for (const QString& file : files) {
        QAction* action = m_recentMenu->addAction(QDir::toNativeSeparators(file));
        connect(action, &QAction::triggered, m_files, [this, file] { m_files->openFile(file); });
    }
    if (!files.isEmpty())
        m_recentMenu->addSeparator();
    QAction* clear
        = m_recentMenu->addAction(tr("&Clear Menu"), m_files, &ProjectFileController::clearRecentFiles);
    clear->setEnabled(!files.isEmpty());
}

void MainWindow::addDock(QDockWidget* dock, Qt::DockWidgetArea area)
{
    Q_ASSERT_X(
        !dock->objectName().isEmpty(), "MainWindow::addDock", "docks need an objectName for the layout");
    dock->setFeatures(
        QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable | QDockWidget::DockWidgetClosable);
    dock->setParent(this);
    // Content taller than the dock scrolls, and content never sets the dock's width
    // (ui/docks/DockScrollArea.h); a dock whose widget scrolls already (Texture Maps) keeps it.
    if (dock->widget() && !qobject_cast<QAbstractScrollArea*>(dock->widget())) {
        QWidget* content = dock->widget();
        dock->setWidget(nullptr); // hides `content`; the scroll area shows it again
        auto* scroll = new DockScrollArea(content, dock);
        scroll->setObjectName(dock->objectName() + QStringLiteral("Scroll"));
        dock->setWidget(scroll);
    }
    addDockWidget(area, dock);
    m_panelsMenu->addAction(dock->toggleViewAction());
}

void MainWindow::createProblemBar()
{
    // A row above the view, shown only while there are problems (ui/widgets/ProblemBar.h). A toolbar row
    // so that the central area (the views' stack) stays as it is; it cannot be moved or hidden
    // from the context menu, and a saved layout does not decide whether it shows.
    m_problemBar = new ProblemBar(this);
    m_problemRow = new QToolBar(tr("Problems"), this);
    m_problemRow->setObjectName(QStringLiteral("problemRow"));
    m_problemRow->setMovable(false);
    m_problemRow->setFloatable(false);
    m_problemRow->toggleViewAction()->setVisible(false);
    m_problemRow->addWidget(m_problemBar);
    m_problemRow->setVisible(false);
    addToolBarBreak(Qt::TopToolBarArea); // a row of its own, the width of the window
    addToolBar(Qt::TopToolBarArea, m_problemRow);
    connect(m_problemBar, &ProblemBar::problemsChanged, m_problemRow, &QWidget::setVisible);

    const auto setProblem
        = [this](const QString& subject, const QString& text) { m_problemBar->setProblem(subject, text); };
    connect(m_scene, &SceneController::problemChanged, this, setProblem);
    connect(m_scene, &SceneController::environmentProblemChanged, this, [this](const QString& problem) {
        m_problemBar->setProblem(QStringLiteral("environment"),
            problem.isEmpty() ? QString()
                              : WindowMessages::environmentNotUsed(problem, m_scene->environmentName()));
    });
    connect(m_files, &ProjectFileController::errorReported, this,
        [this](const QString& text) { m_problemBar->setProblem(QStringLiteral("file"), text); });
    // "Could not save" stayed in the bar after the next save succeeded (issue 29).
    connect(m_files, &ProjectFileController::errorCleared, this,
        [this] { m_problemBar->setProblem(QStringLiteral("file"), QString()); });
    connect(m_autosave, &AutosaveController::failed, this,
        [this](const QString& text) { m_problemBar->setProblem(QStringLiteral("autosave"), text); });
    // Another project: the previous one's problems are not this one's (its own arrive as it loads).
    connect(m_document, &Document::projectReplaced, m_problemBar, &ProblemBar::dismiss);
}

void MainWindow::resetLayout()
{
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        dock->setFloating(false);
        dock->show();
    }
    if (!m_defaultLayout.isEmpty())
        restoreState(m_defaultLayout, kLayoutVersion);
    m_problemRow->setVisible(m_problemBar->hasProblems());
    applyDefaultDockSizes(); // for the window's present width, not the one it first had
    QSettings().remove(kLayoutKey);
}

void MainWindow::applyDefaultDockSizes()
{
    resizeDocks({m_materialsDock}, {width() / kDockColumnWidthDivisor}, Qt::Horizontal);
    const int columnHeight = m_materialsDock->height() + m_textureMapsDock->height();
    const int materialsHeight = int(columnHeight * kMaterialsHeightShare);
    resizeDocks({m_materialsDock, m_textureMapsDock}, {materialsHeight, columnHeight - materialsHeight},
        Qt::Vertical);
}

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
    if (m_layoutRestored)
        return;
    // The layout createDocks() built, sized for the window, is the default; the user's saved one
    // replaces it. Sizes set before the window is shown do not hold: they are set here.
    m_layoutRestored = true;
    QSettings settings;
    restoreGeometry(settings.value(kGeometryKey).toByteArray());
    applyDefaultDockSizes();
    m_defaultLayout = saveState(kLayoutVersion);
    restoreState(settings.value(kLayoutKey).toByteArray(), kLayoutVersion);
    m_problemRow->setVisible(m_problemBar->hasProblems()); // not the saved layout's choice
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kLayoutKey, saveState(kLayoutVersion));
    m_camera->setTurntableRunning(false);
    event->accept();
}

void MainWindow::offerRecovery()
{
    for (const QString& file : m_autosave->orphanedRecoveryFiles()) {
        const QString original = Document::recoveryOriginalPath(file);
        const QString name
            = original.isEmpty() ? tr("an untitled project") : QDir::toNativeSeparators(original);
        const QString when = QFileInfo(file).lastModified().toString(Qt::TextDate);
        const auto answer = QMessageBox::question(this, tr("Recover Unsaved Work"),
            tr("Facet did not close normally. Recover the unsaved changes to %1 (autosaved %2)?")
                .arg(name, when),
            QMessageBox::Yes | QMessageBox::Discard | QMessageBox::Ignore, QMessageBox::Yes);
        if (answer == QMessageBox::Ignore)
            continue; // keep the file for the next start
        if (answer == QMessageBox::Yes) {
            QString error;
            if (!m_document->recover(file, &error)) {
                showStatusMessage(tr("Could not recover %1: %2").arg(file, error));
                continue;
            }
            showStatusMessage(tr("Recovered unsaved changes to %1; save to keep them").arg(name));
        }
        AutosaveController::discard(file);
        if (answer == QMessageBox::Yes)
            break; // one document per window
    }
}

void MainWindow::updateTitle()
{
    setWindowTitle(QStringLiteral("%1[*] — Facet").arg(m_document->displayName()));
    setWindowModified(m_document->isModified());
}

void MainWindow::exportMaterials()
{
    ExportDialog dialog(
        m_document->project(), m_document->exportBaseName(), this, m_document->exportFolder());
    connect(&dialog, &ExportDialog::exported, this, &MainWindow::showStatusMessage);
    dialog.exec();
}

void MainWindow::saveImage()
{
    m_imageSaver->saveImage();
}

bool MainWindow::saveImageTo(const QString& path, QString* error, QSize size, bool transparent)
{
    SaveImageDialog::Choice choice;
    choice.size = size;
    choice.transparent = transparent;
    return m_imageSaver->saveImageTo(path, choice, error);
}

void MainWindow::copyMaterial()
{
    const Material& material = m_document->project().material();
    QGuiApplication::clipboard()->setMimeData(materialMimeData(material));
    showStatusMessage(tr("Copied “%1”: Edit > Paste Material (Ctrl+Shift+V) puts it on another material")
                          .arg(QString::fromStdString(material.name)));
}

void MainWindow::pasteMaterial()
{
    std::string error;
    const std::optional<TransferredMaterial> transferred
        = materialFromMimeData(QGuiApplication::clipboard()->mimeData(), &error);
    if (!transferred) {
        showStatusMessage(error.empty()
                ? tr("The clipboard holds no material (Edit > Copy Material copies one)")
                : tr("The clipboard's material cannot be used: %1").arg(QString::fromStdString(error)));
        return;
    }
    const std::optional<Material> pasted = transferred->material;
    // Everything but the name: the material keeps its place and what the parts call it.
    Material material = *pasted;
    material.name = m_document->project().material().name;
    if (material == m_document->project().material()) {
        showStatusMessage(
            tr("“%1” already looks like the copied material").arg(QString::fromStdString(material.name)));
        return;
    }
    m_document->setMaterial(material, tr("Paste Material"));
    showStatusMessage(tr("Pasted “%1” onto “%2” (factors and maps; the name kept)")
                          .arg(QString::fromStdString(pasted->name), QString::fromStdString(material.name)));
}

void MainWindow::showStatusMessage(const QString& message)
{
    // A message longer than the room left of the frame statistics ends in "…" there, whole in the
    // tooltip (issue 30: it ran into the statistics).
    int room = statusBar()->width() - 24;
    for (QWidget* permanent :
        {static_cast<QWidget*>(m_frameStatsLabel), static_cast<QWidget*>(m_glStatusLabel)})
        if (permanent && permanent->isVisible())
            room -= permanent->width() + 8;
    const QString shown = statusBar()->fontMetrics().elidedText(message, Qt::ElideRight, std::max(room, 120));
    m_fullStatusMessage = message;
    m_shownStatusMessage = shown;
    statusBar()->setToolTip(shown == message ? QString() : message);
    statusBar()->showMessage(shown);
}

QString MainWindow::statusMessage() const
{
    const QString current = statusBar()->currentMessage();
    return current == m_shownStatusMessage ? m_fullStatusMessage : current;
}

QString MainWindow::aboutText() const
{
    QString text = tr("<h3>Facet %1</h3><p>Authoring and previewing physically based materials.</p>")
                       .arg(QStringLiteral(FACET_VERSION));
    text += tr("<p>Qt %1</p>").arg(QString::fromLatin1(qVersion()));
    const GLInfo& gl = m_viewport->glInfo();
    if (gl.isValid()) {
        text += tr("<p>OpenGL %1<br>Renderer: %2<br>Vendor: %3</p>")
                    .arg(QString::fromStdString(gl.version).toHtmlEscaped(),
                        QString::fromStdString(gl.renderer).toHtmlEscaped(),
                        QString::fromStdString(gl.vendor).toHtmlEscaped());
    } else {
        text += tr("<p>OpenGL: not initialised yet</p>");
    }
    return text;
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Facet"), aboutText());
}

void MainWindow::onViewportGLInitialized()
{
    const GLInfo& gl = m_viewport->glInfo();
    const QString summary = QString::fromStdString(gl.summary());
    if (m_viewport->glProblem().isEmpty()) {
        m_glStatusLabel->setText(summary);
        return;
    }
    const QString problem = summary + QStringLiteral(" — ") + m_viewport->glProblem();
    m_glStatusLabel->setText(problem);
    qWarning().noquote() << "facet:" << problem;
}

} // namespace facet
