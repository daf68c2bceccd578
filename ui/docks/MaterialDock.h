#pragma once
// The Material dock: the BRDF (composition, distribution, visibility, Fresnel, dielectric
// coupling, multiple-scattering compensation), the IOR with the F0 it gives, how the base colour's
// alpha is used (opaque, mask with its cutoff, blend) and double-sidedness, a section per layered
// lobe (Clearcoat; shown open while the lobe is on, its sliders made from the material property
// registry's rows), and the preset
// library: the built-in presets (core/material/MaterialPresets.h, the F0 table) and the user's
// (ui/document/UserPresets.h). Apply, Save As Preset…, Delete (user presets only). Edits are undo steps
// (a slider drag is one) on the project's current material (chosen in the Materials dock).

#include "core/material/MaterialProperties.h"
#include "core/shading/ShadingModel.h"
#include "ui/document/DocumentChanges.h"
#include "ui/document/UserPresets.h"

#include <QDockWidget>

#include <functional>
#include <vector>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QFileSystemWatcher;
class QListWidget;
class QListWidgetItem;
class QMimeData;
class QPushButton;
class QTimer;
class QToolButton;

namespace facet {

class ThumbnailLoader;

class ColorButton;
class Document;
class ValueSlider;

class MaterialDock : public QDockWidget {
    Q_OBJECT
public:
    explicit MaterialDock(Document* document, QWidget* parent = nullptr);
    ~MaterialDock() override;

    QListWidget* presetList() const { return m_presets; }
    ValueSlider* iorSlider() const { return m_ior; }
    QComboBox* alphaModeCombo() const { return m_alphaMode; }
    ValueSlider* alphaCutoffSlider() const { return m_alphaCutoff; }
    QCheckBox* doubleSidedCheck() const { return m_doubleSided; }
    QCheckBox* unlitCheck() const { return m_unlit; }
    // The Clearcoat section (KHR_materials_clearcoat): checked when the coat is on; its sliders
    // show only then.
    QGroupBox* clearcoatGroup() const { return m_clearcoatGroup; }
    // The Sheen section (KHR_materials_sheen): checked while the sheen's colour is not black.
    QGroupBox* sheenGroup() const { return m_sheenGroup; }
    QGroupBox* anisotropyGroup() const { return m_anisotropyGroup; }
    QGroupBox* iridescenceGroup() const { return m_iridescenceGroup; }
    // The slider of a registry property the dock shows (the lobes' sliders), or null.
    ValueSlider* propertySlider(MaterialProperty property) const;
    // Applies the selected preset (one undo step). False when none is selected.
    bool applySelectedPreset();
    // The preset of `item` as a dragged material (ui/document/MaterialTransfer.h), named as listed.
    QMimeData* presetMimeData(const QListWidgetItem* item) const;
    // Saves the current material as a user preset named `name` and selects it. False with a
    // message (also emitted) on failure.
    bool saveCurrentAsPreset(const QString& name);
    // Deletes the selected user preset (built-ins cannot be deleted).
    bool deleteSelectedPreset();
    // Re-reads the user presets folder.
    void reloadPresets();
    // Export Package…: the current material with its textures as a preset package named `name`
    // in `folder` (core/material/PresetPackage). Returns its path; empty with a message on failure.
    QString exportCurrentAsPackage(const QString& name, const QString& folder);
    // Import Package…: installs the package at `path` into the user presets and selects it.
    bool importPackage(const QString& path);
    // Add Folder…: lists the presets of `folder` with the user's (UserPresets::addFolder).
    bool addPresetFolder(const QString& folder);
    // Save to Library (with textures): the current material as a preset package named `name` in
    // the user's presets folder, listed and selected at once. False with a message on failure.
    bool saveCurrentToLibrary(const QString& name);
    // The list's search (by name, any case): presets whose label does not contain `text` are
    // hidden; empty shows every one.
    void filterPresets(const QString& text);
    // Large swatches (kLargeSwatchSize, a grid of them) or a list of small ones (kSwatchSize);
    // remembered (QSettings presets/largeSwatches).
    void setLargeSwatches(bool large);
    bool largeSwatches() const { return m_largeSwatches; }
    // Swatches still being rendered for the list (each preset's icon, ui/viewport/ThumbnailLoader).
    int pendingSwatches() const;
    // The preset folders watched for files added, changed or removed: the list follows within
    // kWatchDelayMs without a restart.
    QStringList watchedFolders() const;
    static constexpr int kSwatchSize = 40;
    static constexpr int kLargeSwatchSize = 96;
    static constexpr int kWatchDelayMs = 300;

Q_SIGNALS:
    void message(const QString& text);

private:
    void onDocumentChanged(DocumentChanges changes);
    void editShading(const QString& undoText, const std::function<void(ShadingModel&)>& change);
    void askPresetName();
    void askExportPackage();
    void askImportPackage();
    void updatePresetButtons();
    // A slider for a registry row: its range, label and undo merge id from the row; an edit sets
    // the value on the current material as one undo step per drag.
    ValueSlider* addPropertySlider(MaterialProperty property, QFormLayout* form, const QString& label);
    // A lobe's section: a checkable group whose check turns the lobe on and off (`setOn` changes
    // the material: a strength to 1 or 0, a colour to white or black), and whose controls show
    // only while it is on.
    QGroupBox* addLobeSection(const QString& title, std::function<void(Material&, bool)> setOn,
        QWidget* parent, QFormLayout** form);

    Document* m_document;
    QLineEdit* m_name;
    QComboBox* m_composition;
    QComboBox* m_distribution;
    QComboBox* m_visibility;
    QComboBox* m_fresnel;
    QComboBox* m_coupling;
    QCheckBox* m_multiScatter;
    ValueSlider* m_ior = nullptr; // the registry's rows (addPropertySlider)
    QLabel* m_f0;
    QComboBox* m_alphaMode;
    ValueSlider* m_alphaCutoff = nullptr;
    QCheckBox* m_doubleSided;
    QCheckBox* m_unlit;
    QGroupBox* m_clearcoatGroup = nullptr;
    QGroupBox* m_sheenGroup = nullptr;
    QGroupBox* m_anisotropyGroup = nullptr;
    QGroupBox* m_iridescenceGroup = nullptr;
    ColorButton* m_sheenColor = nullptr;
    ColorButton* m_specularColor = nullptr;
    std::vector<std::pair<MaterialProperty, ValueSlider*>> m_propertySliders;
    QListWidget* m_presets;
    QPushButton* m_apply;
    QPushButton* m_delete;
    std::vector<UserPreset> m_userPresets;
    ThumbnailLoader* m_swatches = nullptr;
    QLineEdit* m_search = nullptr;
    QToolButton* m_largeButton = nullptr;
    QFileSystemWatcher* m_watcher = nullptr;
    QTimer* m_watchDelay = nullptr;
    bool m_largeSwatches = false;
    int swatchSize() const { return m_largeSwatches ? kLargeSwatchSize : kSwatchSize; }
    void watchFolders();
};

} // namespace facet
