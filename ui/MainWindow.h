#pragma once
// Facet's main window. It wires and does little else: the Document (model and undo stack), the
// SceneController and the central ViewportWidget (the view), the CameraController (input), the
// PartPicker (a click on a part chooses its material) and the ViewportDropHandler (assets dropped
// on the view), the ProjectFileController (File menu) and the AutosaveController (recovery); menus, the
// status bar (what it says about the views: ui/viewport/ViewStatus), the dock layout and its QSettings.
// Panels are QDockWidgets made by their own controllers and plugged in with addDock(); they edit the
// document() and never the renderer.

#include <QByteArray>
#include <QMainWindow>
#include <QSize>

class QAction;
class QDockWidget;
class QLabel;
class QToolBar;
class QMenu;

namespace facet {

class ViewStatus;

class AutosaveController;
class CameraController;
class CompareActions;
class CompareController;
class ProblemBar;
class CompareView;
class Document;
class EnvironmentDock;
class LightsDock;
class MaterialDock;
class MaterialsDock;
class PartPicker;
class ProjectFileController;
class DocumentAssets;
class FreedMemoryTimer;
class ImageSaver;
class MaterialDropHandler;
class SceneController;
class TextureMapsDock;
class ValuePicker;
class ValuesDock;
class ViewDock;
class ViewportDropHandler;
class ViewportWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // `recoveryDirectory` empty: AutosaveController::defaultDirectory().
    explicit MainWindow(QWidget* parent = nullptr, const QString& recoveryDirectory = {});
    ~MainWindow() override;

    Document* document() const { return m_document; }
    SceneController* sceneController() const { return m_scene; }
    ViewportWidget* viewport() const { return m_viewport; }
    CameraController* cameraController() const { return m_camera; }
    ProjectFileController* projectFiles() const { return m_files; }
    AutosaveController* autosave() const { return m_autosave; }
    TextureMapsDock* textureMapsDock() const { return m_textureMapsDock; }
    MaterialDock* materialDock() const { return m_materialDock; }
    MaterialsDock* materialsDock() const { return m_materialsDock; }
    PartPicker* partPicker() const { return m_picker; }
    // View > Value Picker and the Values dock it fills (ui/viewport/ValuePicker.h).
    ValuePicker* valuePicker() const { return m_valuePicker; }
    ValuesDock* valuesDock() const { return m_valuesDock; }
    ViewportDropHandler* viewportDrops() const { return m_drops; }
    // Materials and presets dropped on a part of the mesh (ui/document/MaterialTransfer.h).
    MaterialDropHandler* materialDrops() const { return m_materialDrops; }
    EnvironmentDock* environmentDock() const { return m_environmentDock; }
    LightsDock* lightsDock() const { return m_lightsDock; }
    ViewDock* viewDock() const { return m_viewDock; }
    CompareView* compareView() const { return m_compareView; }
    CompareController* compareController() const { return m_compareController; }
    CompareActions* compareActions() const { return m_compareActions; }
    // Problems that stay in view until dismissed (ui/widgets/ProblemBar.h).
    ProblemBar* problemBar() const { return m_problemBar; }

    // Adds a panel: docked in `area`, movable, floatable, closable, tabbable; its toggle goes
    // into View > Panels. Its content goes into a DockScrollArea (unless it is a scroll area), so
    // that what it holds never sets the dock's width. The dock needs a unique objectName (the
    // saved layout refers to it). Add docks before the window is first shown so that the saved
    // layout applies to them.
    void addDock(QDockWidget* dock, Qt::DockWidgetArea area = Qt::RightDockWidgetArea);
    // View > Reset Layout: every panel back in the default layout (one column on the right, a
    // quarter of the window's present width), visible, docked.
    void resetLayout();

    // Shows a message in the status bar until the next one (e.g. a warning from the command line).
    void showStatusMessage(const QString& message);
    QString statusMessage() const;
    // The About box's text: version, Qt, and the viewport's OpenGL (once initialised).
    QString aboutText() const;
    // Asks whether to recover the work of a session that crashed (one question per recovery
    // file, newest first); main() calls it once the window is shown.
    void offerRecovery();
    // File > Export…: the document's materials as a glTF asset or an engine's texture set
    // (ui/dialogs/ExportDialog); what it wrote goes to the status bar.
    void exportMaterials();
    // Edit > Copy Material / Paste Material (Ctrl+Shift+C / V): the current material's factors,
    // maps and options through the clipboard onto the current material, whose name stays; one undo
    // step. The status bar says what happened, or why nothing did.
    void copyMaterial();
    void pasteMaterial();
    // File > Save Image… (F12, ui/dialogs/ImageSaver): the single view as a PNG (what it shows: its
    // display transform) or a linear EXR (scene radiance), rendered again offscreen at the chosen
    // size (ui/dialogs/SaveImageDialog: the view's own by default) and converged to the project's IBL
    // samples; in a Compare mode the grid as shown, PNG only. saveImageTo() is the part after the
    // dialogs (`size` empty: the view's own): false with *error (also in the status bar).
    // File > Save Turntable… (Shift+F12) is imageSaver()'s.
    void saveImage();
    bool saveImageTo(const QString& path, QString* error, QSize size = {}, bool transparent = false);
    ImageSaver* imageSaver() const { return m_imageSaver; }
    // Edit > Preferences…: this computer's settings (ui/dialogs/PreferencesDialog: the cache budget).
    void showPreferences();

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void createMenus();
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void createDocks();
    void applyDefaultDockSizes();
    void createProblemBar();
    void updateRecentFilesMenu();
    void updateTitle();
    void showAbout();
    void onViewportGLInitialized();

    Document* m_document = nullptr;
    DocumentAssets* m_assets = nullptr; // environments, meshes and maps, shared by the views
    SceneController* m_scene = nullptr;
    ViewportWidget* m_viewport = nullptr;
    CameraController* m_camera = nullptr;
    ProjectFileController* m_files = nullptr;
    PartPicker* m_picker = nullptr;
    ValuePicker* m_valuePicker = nullptr;
    ValuesDock* m_valuesDock = nullptr;
    FreedMemoryTimer* m_freedMemory = nullptr; // hands freed memory back to the system
    ImageSaver* m_imageSaver = nullptr; // File > Save Image…, Save Turntable…
    ViewportDropHandler* m_drops = nullptr;
    MaterialDropHandler* m_materialDrops = nullptr; // installed after m_drops: sees drags first
    AutosaveController* m_autosave = nullptr;
    CompareController* m_compareController = nullptr;
    CompareView* m_compareView = nullptr;
    CompareActions* m_compareActions = nullptr;
    QAction* m_helpMenuAction = nullptr;
    TextureMapsDock* m_textureMapsDock = nullptr;
    MaterialDock* m_materialDock = nullptr;
    MaterialsDock* m_materialsDock = nullptr;
    EnvironmentDock* m_environmentDock = nullptr;
    LightsDock* m_lightsDock = nullptr;
    ViewDock* m_viewDock = nullptr;
    QLabel* m_glStatusLabel = nullptr;
    QLabel* m_frameStatsLabel = nullptr;
    ViewStatus* m_viewStatus = nullptr;
    // The last showStatusMessage() whole, and as shown (elided to the room left of the statistics).
    QString m_fullStatusMessage;
    QString m_shownStatusMessage;
    ProblemBar* m_problemBar = nullptr;
    QToolBar* m_problemRow = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_panelsMenu = nullptr;
    QAction* m_relinkAction = nullptr;
    QByteArray m_defaultLayout;
    bool m_layoutRestored = false;
};

} // namespace facet
