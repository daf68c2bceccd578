#include "ui/docks/MaterialDock.h"
#include "ui/viewport/ThumbnailLoader.h"

#include "core/material/MaterialPresets.h"
#include "core/shading/MaterialBrdf.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"
#include "ui/document/MaterialTransfer.h"
#include "ui/widgets/ColorButton.h"
#include "ui/widgets/ValueSlider.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QIcon>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPixmap>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace facet {

namespace {

// List item data: the built-in preset's index, or the user preset's index + kUserOffset.
constexpr int kPresetRole = Qt::UserRole;
constexpr int kSwatchKeyRole = Qt::UserRole + 1; // "builtin|<id>" or "user|<path>"
constexpr int kUserOffset = 100000;

template <typename Enum>
QComboBox* enumCombo(QWidget* parent, const char* name, std::initializer_list<std::pair<Enum, QString>> items)
{
    auto* combo = new QComboBox(parent);
    combo->setObjectName(QLatin1String(name));
    for (const auto& [value, text] : items)
        combo->addItem(text, int(value));
    return combo;
}

void select(QComboBox* combo, int value)
{
    const QSignalBlocker blocker(combo);
    combo->setCurrentIndex(combo->findData(value));
}

} // namespace

MaterialDock::MaterialDock(Document* document, QWidget* parent)
    : QDockWidget(tr("Material"), parent)
    , m_document(document)
    , m_name(new QLineEdit(this))
    , m_f0(new QLabel(this))
    , m_doubleSided(new QCheckBox(tr("Double-sided"), this))
    , m_unlit(new QCheckBox(tr("Unlit"), this))
    , m_presets(new QListWidget(this))
    , m_apply(new QPushButton(tr("Apply"), this))
    , m_delete(new QPushButton(tr("Delete"), this))
{
    setObjectName(QStringLiteral("materialDock"));
    m_composition = enumCombo<BrdfComposition>(this, "brdfComposition",
        {{BrdfComposition::Gltf, tr("glTF 2.0")}, {BrdfComposition::LearnOpenGL, tr("LearnOpenGL / UE4")}});
    m_distribution = enumCombo<Distribution>(
        this, "brdfDistribution", {{Distribution::GGX, tr("GGX")}, {Distribution::Beckmann, tr("Beckmann")}});
    m_visibility = enumCombo<Visibility>(this, "brdfVisibility",
        {{Visibility::SmithGGXCorrelated, tr("Smith-GGX height-correlated")},
            {Visibility::SmithGGXUncorrelated, tr("Smith-GGX separable")},
            {Visibility::SchlickGGX, tr("Schlick-GGX")}});
    m_fresnel = enumCombo<Fresnel>(this, "brdfFresnel",
        {{Fresnel::Schlick, tr("Schlick")}, {Fresnel::Dielectric, tr("Exact dielectric")}});
    m_coupling = enumCombo<DielectricCoupling>(this, "brdfCoupling",
        {{DielectricCoupling::FresnelMix, tr("glTF fresnel_mix")},
            {DielectricCoupling::EnergyPreserving, tr("Energy-preserving")}});
    m_alphaMode = enumCombo<AlphaMode>(this, "alphaMode",
        {{AlphaMode::Opaque, tr("Opaque")}, {AlphaMode::Mask, tr("Mask (cut-out)")},
            {AlphaMode::Blend, tr("Blend (transparent)")}});
    m_alphaMode->setToolTip(tr("How the base colour's alpha is used (glTF alphaMode): ignored, a cut-out "
                               "below the cutoff, or blended over what is behind"));
    m_doubleSided->setObjectName(QStringLiteral("doubleSidedCheck"));
    m_doubleSided->setToolTip(
        tr("Draw faces seen from behind too (off: they are culled, as glTF's default)"));
    // Short enough for a narrow dock column; the tooltip says what it is.
    m_multiScatter = new QCheckBox(tr("Multiple scattering"), this);
    m_multiScatter->setObjectName(QStringLiteral("multiScatterCheck"));
    m_multiScatter->setToolTip(
        tr("Multiple-scattering compensation: gives back the energy that single-scattering "
           "GGX loses at high roughness (docs/energy.md)"));
    m_name->setObjectName(QStringLiteral("materialName"));
    m_f0->setObjectName(QStringLiteral("f0Label"));

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    auto* form = new QFormLayout;
    form->addRow(tr("Name"), m_name);
    m_ior = addPropertySlider(MaterialProperty::Ior, form, tr("IOR"));
    form->addRow(tr("F0"), m_f0);
    layout->addLayout(form);
    // KHR_materials_specular is the dielectric's own reflectance, not a layer over it: its defaults
    // (strength 1, white) are the glTF core's, so the section is always open, beside the IOR.
    auto* specularGroup = new QGroupBox(tr("Specular"), content);
    specularGroup->setObjectName(QStringLiteral("specularGroup"));
    specularGroup->setToolTip(tr("KHR_materials_specular: the strength of the dielectric's reflection (0: "
                                 "purely diffuse) and a tint of its F0 (values above 1 raise it beyond the "
                                 "IOR's); metals ignore both"));
    auto* specularForm = new QFormLayout(specularGroup);
    addPropertySlider(MaterialProperty::Specular, specularForm, tr("Strength"));
    m_specularColor = new ColorButton(specularGroup);
    m_specularColor->setObjectName(QStringLiteral("specularColorDockButton"));
    specularForm->addRow(tr("Colour"), m_specularColor);
    connect(m_specularColor, &ColorButton::colorEdited, this, [this](const glm::dvec3& linear) {
        Material material = m_document->project().material();
        setColor(material, MaterialProperty::SpecularColor, linear);
        m_document->setMaterial(material, tr("Specular Colour"));
    });
    layout->addWidget(specularGroup);
    // The layered lobes (docs/shading.md): a section each, open while the lobe is on, above the
    // alpha and BRDF settings (what an artist reaches for first).
    QFormLayout* clearcoatForm = nullptr;
    m_clearcoatGroup = addLobeSection(
        tr("Clearcoat"), [](Material& m, bool on) { m.setFactor(MapSlot::Clearcoat, on ? 1.0 : 0.0); },
        content, &clearcoatForm);
    m_clearcoatGroup->setObjectName(QStringLiteral("clearcoatGroup"));
    m_clearcoatGroup->setToolTip(tr("KHR_materials_clearcoat: a clear lacquer (IOR 1.5) over the material, "
                                    "with its own roughness: car paint, varnished wood, coated plastic"));
    addPropertySlider(MaterialProperty::Clearcoat, clearcoatForm, tr("Strength"));
    addPropertySlider(MaterialProperty::ClearcoatRoughness, clearcoatForm, tr("Roughness"));
    layout->addWidget(m_clearcoatGroup);
    QFormLayout* sheenForm = nullptr;
    m_sheenGroup = addLobeSection(
        tr("Sheen"),
        [](Material& m, bool on) {
            // On: a white sheen of middle roughness (a roughness-0 sheen is a hairline at the
            // silhouette); off: black, the roughness kept for the next time.
            m.setSheen(
                glm::dvec3(on ? 1.0 : 0.0), on && m.sheenRoughness() == 0.0 ? 0.5 : m.sheenRoughness());
        },
        content, &sheenForm);
    m_sheenGroup->setObjectName(QStringLiteral("sheenGroup"));
    m_sheenGroup->setToolTip(tr("KHR_materials_sheen: a soft back-scattering layer of fibres over the "
                                "material, brightest at grazing angles: cloth, velvet, dust, peach fuzz"));
    m_sheenColor = new ColorButton(m_sheenGroup);
    m_sheenColor->setObjectName(QStringLiteral("sheenColorDockButton"));
    m_sheenColor->setToolTip(QString::fromUtf8(infoOf(MaterialProperty::SheenColor).label));
    sheenForm->addRow(tr("Colour"), m_sheenColor);
    connect(m_sheenColor, &ColorButton::colorEdited, this, [this](const glm::dvec3& linear) {
        Material material = m_document->project().material();
        setColor(material, MaterialProperty::SheenColor, linear);
        m_document->setMaterial(material, tr("Sheen Colour"));
    });
    addPropertySlider(MaterialProperty::SheenRoughness, sheenForm, tr("Roughness"));
    layout->addWidget(m_sheenGroup);
    QFormLayout* anisotropyForm = nullptr;
    m_anisotropyGroup = addLobeSection(
        tr("Anisotropy"),
        // On: the strength 0.5 of a lightly brushed metal; off: 0, the rotation kept.
        [](Material& m, bool on) { m.setFactor(MapSlot::Anisotropy, on ? 0.5 : 0.0); }, content, &anisotropyForm);
    m_anisotropyGroup->setObjectName(QStringLiteral("anisotropyGroup"));
    m_anisotropyGroup->setToolTip(tr("KHR_materials_anisotropy: the highlight stretched along a direction of "
                                     "the surface (the mesh's tangent, turned by the rotation, or a direction "
                                     "texture): brushed metal, hair, satin, a vinyl record"));
    addPropertySlider(MaterialProperty::Anisotropy, anisotropyForm, tr("Strength"));
    addPropertySlider(MaterialProperty::AnisotropyRotation, anisotropyForm, tr("Rotation"));
    layout->addWidget(m_anisotropyGroup);
    QFormLayout* iridescenceForm = nullptr;
    m_iridescenceGroup = addLobeSection(
        tr("Iridescence"),
        // On: a full film at the extension's defaults (index 1.3, 100-400 nm); off: factor 0, the
        // film's index and thicknesses kept.
        [](Material& m, bool on) { m.setFactor(MapSlot::Iridescence, on ? 1.0 : 0.0); }, content, &iridescenceForm);
    m_iridescenceGroup->setObjectName(QStringLiteral("iridescenceGroup"));
    m_iridescenceGroup->setToolTip(tr("KHR_materials_iridescence: a thin film over the surface whose interference "
                                      "colours the reflection by angle and thickness: soap bubbles, oil on water, "
                                      "coated lenses, heat-tinted metal, beetle shells"));
    addPropertySlider(MaterialProperty::Iridescence, iridescenceForm, tr("Strength"));
    addPropertySlider(MaterialProperty::IridescenceIor, iridescenceForm, tr("Film IOR"));
    addPropertySlider(MaterialProperty::IridescenceThickness, iridescenceForm, tr("Thickness"))->setSuffix(tr(" nm"));
    ValueSlider* minimum = addPropertySlider(MaterialProperty::IridescenceThicknessMinimum, iridescenceForm, tr("Min"));
    minimum->setSuffix(tr(" nm"));
    minimum->setToolTip(tr("The film's thickness where a thickness texture reads 0 (the thickness above is where it "
                           "reads 1, and everywhere without a texture)"));
    layout->addWidget(m_iridescenceGroup);
    auto* surfaceGroup = new QGroupBox(tr("Alpha and Sides"), content);
    auto* surfaceForm = new QFormLayout(surfaceGroup);
    surfaceForm->addRow(tr("Alpha"), m_alphaMode);
    m_alphaCutoff = addPropertySlider(MaterialProperty::AlphaCutoff, surfaceForm, tr("Cutoff"));
    m_alphaCutoff->setToolTip(tr("Mask: texels whose alpha is below this are not drawn"));
    surfaceForm->addRow(m_doubleSided); // spans the row: its text fits a narrow dock column
    m_unlit->setObjectName(QStringLiteral("unlitCheck"));
    m_unlit->setToolTip(tr("KHR_materials_unlit: the surface shows its base colour (factor, texture and "
                           "vertex colour) as it is, with no lighting, environment or emission: for baked "
                           "lighting, stylised assets and scans."));
    surfaceForm->addRow(m_unlit);
    layout->addWidget(surfaceGroup);
    auto* brdfGroup = new QGroupBox(tr("BRDF"), content);
    auto* brdfForm = new QFormLayout(brdfGroup);
    brdfForm->addRow(tr("Composition"), m_composition);
    brdfForm->addRow(tr("Distribution"), m_distribution);
    brdfForm->addRow(tr("Visibility"), m_visibility);
    brdfForm->addRow(tr("Fresnel"), m_fresnel);
    brdfForm->addRow(tr("Dielectric"), m_coupling);
    brdfForm->addRow(m_multiScatter); // spans the row: its text fits a narrow dock column
    layout->addWidget(brdfGroup);

    auto* presetGroup = new QGroupBox(tr("Presets"), content);
    auto* presetLayout = new QVBoxLayout(presetGroup);
    m_presets->setObjectName(QStringLiteral("presetList"));
    // A preset dragged onto a part in the viewport becomes a material of the project, on that part
    // (ui/document/MaterialTransfer.h).
    makeMaterialDragSource(m_presets, [this](const QListWidgetItem* item) { return presetMimeData(item); });
    m_presets->setIconSize(QSize(kSwatchSize, kSwatchSize));
    // Five swatch rows before it scrolls (issue 30: it showed one or two until resized).
    m_presets->setMinimumHeight(5 * (kSwatchSize + 6) + 4);
    // The library's search and swatch size (issue 30: a library browser).
    m_search = new QLineEdit(presetGroup);
    m_search->setObjectName(QStringLiteral("presetSearch"));
    m_search->setPlaceholderText(tr("Search presets"));
    m_search->setClearButtonEnabled(true);
    connect(m_search, &QLineEdit::textChanged, this, &MaterialDock::filterPresets);
    m_largeButton = new QToolButton(presetGroup);
    m_largeButton->setObjectName(QStringLiteral("largeSwatchesButton"));
    m_largeButton->setText(tr("Large"));
    m_largeButton->setCheckable(true);
    m_largeButton->setToolTip(tr("Large swatches in a grid, or a list of small ones"));
    connect(m_largeButton, &QToolButton::toggled, this, &MaterialDock::setLargeSwatches);
    auto* searchRow = new QHBoxLayout;
    searchRow->addWidget(m_search, 1);
    searchRow->addWidget(m_largeButton);
    presetLayout->addLayout(searchRow);
    m_swatches = new ThumbnailLoader(this);
    connect(m_swatches, &ThumbnailLoader::ready, this,
        [this](const QString& key, const QImage& image, QSize, const QString&, double) {
            if (image.isNull())
                return;
            for (int row = 0; row < m_presets->count(); ++row)
                if (m_presets->item(row)->data(kSwatchKeyRole).toString() == key)
                    m_presets->item(row)->setIcon(QIcon(QPixmap::fromImage(image)));
        });
    presetLayout->addWidget(m_presets);
    auto* saveAs = new QPushButton(tr("Save As…"), presetGroup);
    m_apply->setObjectName(QStringLiteral("applyPresetButton"));
    saveAs->setObjectName(QStringLiteral("savePresetButton"));
    m_delete->setObjectName(QStringLiteral("deletePresetButton"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_apply);
    buttons->addWidget(saveAs);
    buttons->addWidget(m_delete);
    presetLayout->addLayout(buttons);
    // Packages (a preset with its textures, to move between machines) and shared folders: one menu,
    // so the dock keeps the width of its default layout.
    auto* library = new QToolButton(presetGroup);
    library->setObjectName(QStringLiteral("presetLibraryButton"));
    library->setText(tr("Packages and Folders"));
    library->setPopupMode(QToolButton::InstantPopup);
    library->setToolButtonStyle(Qt::ToolButtonTextOnly);
    library->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    auto* libraryMenu = new QMenu(library);
    QAction* importPackage = libraryMenu->addAction(tr("Import Package…"));
    importPackage->setObjectName(QStringLiteral("importPackageAction"));
    importPackage->setToolTip(tr("Add a preset package (.facetpreset folder) to your presets"));
    QAction* saveToLibrary = libraryMenu->addAction(tr("Save to Library…"));
    saveToLibrary->setObjectName(QStringLiteral("saveToLibraryAction"));
    saveToLibrary->setToolTip(
        tr("Save the current material with its textures into your presets, as a preset package"));
    connect(saveToLibrary, &QAction::triggered, this, [this] {
        bool ok = false;
        const QString name = QInputDialog::getText(this, tr("Save to Library"), tr("Preset name:"),
            QLineEdit::Normal, QString::fromStdString(m_document->project().material().name), &ok);
        if (ok)
            saveCurrentToLibrary(name);
    });
    QAction* exportPackage = libraryMenu->addAction(tr("Export Package…"));
    exportPackage->setObjectName(QStringLiteral("exportPackageAction"));
    exportPackage->setToolTip(tr("Write the current material with its textures as a preset package (a "
                                 ".facetpreset folder) that another Facet imports"));
    libraryMenu->addSeparator();
    QAction* addFolder = libraryMenu->addAction(tr("Add Folder…"));
    addFolder->setObjectName(QStringLiteral("addPresetFolderAction"));
    addFolder->setToolTip(tr("List the presets and packages of a folder (a shared library) with yours"));
    libraryMenu->setToolTipsVisible(true);
    library->setMenu(libraryMenu);
    connect(addFolder, &QAction::triggered, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Add Preset Folder"));
        if (!folder.isEmpty())
            addPresetFolder(folder);
    });
    presetLayout->addWidget(library);
    connect(exportPackage, &QAction::triggered, this, &MaterialDock::askExportPackage);
    connect(importPackage, &QAction::triggered, this, &MaterialDock::askImportPackage);
    layout->addWidget(presetGroup, 1);
    setWidget(content);
    // Files added to a preset folder appear without a restart (a short delay gathers a copy of
    // many files into one reload).
    m_watcher = new QFileSystemWatcher(this);
    m_watchDelay = new QTimer(this);
    m_watchDelay->setSingleShot(true);
    m_watchDelay->setInterval(kWatchDelayMs);
    connect(m_watcher, &QFileSystemWatcher::directoryChanged, m_watchDelay, qOverload<>(&QTimer::start));
    connect(m_watchDelay, &QTimer::timeout, this, &MaterialDock::reloadPresets);

    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        Material material = m_document->project().material();
        const std::string name = m_name->text().trimmed().toStdString();
        if (name.empty() || name == material.name)
            return;
        material.name = name;
        m_document->setMaterial(material, tr("Rename Material"));
    });
    connect(m_alphaMode, &QComboBox::activated, this, [this] {
        Material material = m_document->project().material();
        material.alphaMode = AlphaMode(m_alphaMode->currentData().toInt());
        m_document->setMaterial(material, tr("Alpha Mode"));
    });
    connect(m_doubleSided, &QCheckBox::clicked, this, [this](bool on) {
        Material material = m_document->project().material();
        material.doubleSided = on;
        m_document->setMaterial(material, on ? tr("Double-sided") : tr("Single-sided"));
    });
    connect(m_unlit, &QCheckBox::clicked, this, [this](bool on) {
        Material material = m_document->project().material();
        material.unlit = on;
        m_document->setMaterial(material, on ? tr("Unlit") : tr("Lit"));
    });
    const auto connectCombo = [this](QComboBox* combo, const QString& undoText, auto apply) {
        connect(combo, &QComboBox::activated, this, [this, combo, undoText, apply] {
            const int value = combo->currentData().toInt();
            editShading(undoText, [&](ShadingModel& model) { apply(model, value); });
        });
    };
    connectCombo(m_composition, tr("BRDF Composition"),
        [](ShadingModel& m, int v) { m.composition = BrdfComposition(v); });
    connectCombo(m_distribution, tr("BRDF Distribution"),
        [](ShadingModel& m, int v) { m.distribution = Distribution(v); });
    connectCombo(
        m_visibility, tr("BRDF Visibility"), [](ShadingModel& m, int v) { m.visibility = Visibility(v); });
    connectCombo(m_fresnel, tr("BRDF Fresnel"), [](ShadingModel& m, int v) { m.fresnel = Fresnel(v); });
    connectCombo(m_coupling, tr("Dielectric Coupling"),
        [](ShadingModel& m, int v) { m.coupling = DielectricCoupling(v); });
    connect(m_multiScatter, &QCheckBox::clicked, this, [this](bool on) {
        editShading(on ? tr("Multiple Scattering On") : tr("Multiple Scattering Off"),
            [on](ShadingModel& model) { model.multiScatter = on; });
    });
    connect(m_apply, &QPushButton::clicked, this, &MaterialDock::applySelectedPreset);
    connect(m_presets, &QListWidget::itemDoubleClicked, this, &MaterialDock::applySelectedPreset);
    connect(m_presets, &QListWidget::currentItemChanged, this, &MaterialDock::updatePresetButtons);
    connect(saveAs, &QPushButton::clicked, this, &MaterialDock::askPresetName);
    connect(m_delete, &QPushButton::clicked, this, [this] {
        const QListWidgetItem* item = m_presets->currentItem();
        if (!item)
            return;
        const auto answer = QMessageBox::question(this, tr("Delete Preset"),
            tr("Delete the preset “%1”? This cannot be undone.").arg(item->text()));
        if (answer == QMessageBox::Yes)
            deleteSelectedPreset();
    });
    connect(m_document, &Document::changed, this, &MaterialDock::onDocumentChanged);
    m_largeSwatches = QSettings().value(QStringLiteral("presets/largeSwatches"), false).toBool();
    {
        const QSignalBlocker blocker(m_largeButton);
        m_largeButton->setChecked(m_largeSwatches);
    }
    setLargeSwatches(m_largeSwatches);
    reloadPresets();
    onDocumentChanged(DocumentChange::WholeProject);
}

QGroupBox* MaterialDock::addLobeSection(
    const QString& title, std::function<void(Material&, bool)> setOn, QWidget* parent, QFormLayout** form)
{
    auto* group = new QGroupBox(title, parent);
    group->setCheckable(true);
    auto* body = new QWidget(group);
    auto* groupLayout = new QVBoxLayout(group);
    groupLayout->setContentsMargins(0, 0, 0, 0);
    groupLayout->addWidget(body);
    *form = new QFormLayout(body);
    connect(group, &QGroupBox::toggled, body, &QWidget::setVisible);
    connect(group, &QGroupBox::clicked, this, [this, setOn = std::move(setOn), title](bool on) {
        Material material = m_document->project().material();
        setOn(material, on);
        m_document->setMaterial(material, on ? tr("%1 On").arg(title) : tr("%1 Off").arg(title));
    });
    return group;
}

ValueSlider* MaterialDock::addPropertySlider(
    MaterialProperty property, QFormLayout* form, const QString& label)
{
    const MaterialPropertyInfo& info = infoOf(property);
    ValueSlider* slider = ValueSlider::forProperty(info, this);
    slider->setObjectName(QLatin1String(info.name) + QLatin1String("Slider"));
    form->addRow(label, slider);
    m_propertySliders.emplace_back(property, slider);
    connect(slider, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
    connect(slider, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
    connect(slider, &ValueSlider::valueEdited, this, [this, property](double value) {
        Material material = m_document->project().material();
        setScalar(material, property, value);
        m_document->setMaterial(
            material, QString::fromUtf8(infoOf(property).label), MergeId::MaterialProperty0 + int(property));
    });
    return slider;
}

ValueSlider* MaterialDock::propertySlider(MaterialProperty property) const
{
    for (const auto& [p, slider] : m_propertySliders)
        if (p == property)
            return slider;
    return nullptr;
}

void MaterialDock::setLargeSwatches(bool large)
{
    const bool changed = large != m_largeSwatches;
    m_largeSwatches = large;
    QSettings().setValue(QStringLiteral("presets/largeSwatches"), large);
    {
        const QSignalBlocker blocker(m_largeButton);
        m_largeButton->setChecked(large);
    }
    const int side = swatchSize();
    m_presets->setViewMode(large ? QListView::IconMode : QListView::ListMode);
    m_presets->setIconSize(QSize(side, side));
    m_presets->setResizeMode(QListView::Adjust);
    m_presets->setMovement(QListView::Static);
    m_presets->setWordWrap(large);
    // A grid cell a swatch wide with two lines of name under it.
    m_presets->setGridSize(large ? QSize(side + 24, side + 2 * fontMetrics().lineSpacing() + 10) : QSize());
    if (changed)
        reloadPresets(); // the swatches again, at the new size
}

void MaterialDock::filterPresets(const QString& text)
{
    const QString wanted = text.trimmed();
    for (int row = 0; row < m_presets->count(); ++row) {
        QListWidgetItem* item = m_presets->item(row);
        item->setHidden(!wanted.isEmpty() && !item->text().contains(wanted, Qt::CaseInsensitive));
    }
}

QStringList MaterialDock::watchedFolders() const
{
    return m_watcher ? m_watcher->directories() : QStringList();
}

void MaterialDock::watchFolders()
{
    if (!m_watcher)
        return;
    QStringList wanted = UserPresets::folders();
    // The user's own folder once it exists (made by the first save).
    if (QFileInfo(UserPresets::directory()).isDir())
        wanted.prepend(UserPresets::directory());
    const QStringList watched = m_watcher->directories();
    for (const QString& folder : watched)
        if (!wanted.contains(folder))
            m_watcher->removePath(folder);
    for (const QString& folder : wanted)
        if (!watched.contains(folder) && QFileInfo(folder).isDir())
            m_watcher->addPath(folder);
}

bool MaterialDock::saveCurrentToLibrary(const QString& name)
{
    if (!QDir().mkpath(UserPresets::directory())) {
        Q_EMIT message(tr("Could not save to the library: cannot make %1").arg(UserPresets::directory()));
        return false;
    }
    const QString path = exportCurrentAsPackage(name, UserPresets::directory());
    if (path.isEmpty())
        return false;
    reloadPresets();
    for (int row = 0; row < m_presets->count(); ++row)
        if (m_presets->item(row)->toolTip() == path)
            m_presets->setCurrentRow(row);
    Q_EMIT message(tr("Saved “%1” to your library, with its textures").arg(name.trimmed()));
    return true;
}

MaterialDock::~MaterialDock() = default;

void MaterialDock::onDocumentChanged(DocumentChanges changes)
{
    if (!(changes
            & (DocumentChanges(DocumentChange::MaterialFactors) | DocumentChange::Shading
                | DocumentChange::CurrentMaterial)))
        return;
    const Material& material = m_document->project().material();
    // While the name is being typed it stays, unless another material was chosen: then the field
    // must show that one's name, or finishing the edit would rename it.
    if (!m_name->hasFocus() || changes.testFlag(DocumentChange::CurrentMaterial))
        m_name->setText(QString::fromStdString(material.name));
    // The dielectric's F0 as shaded: the IOR's, tinted and scaled by KHR_materials_specular.
    MaterialInfo layerInputs;
    layerInputs.ior = material.ior;
    layerInputs.specular = material.specular();
    layerInputs.specularColor = material.specularColor();
    const glm::dvec3 f0 = dielectricReflectance(layerInputs).f0;
    m_f0->setText(f0.r == f0.g && f0.g == f0.b
            ? QString::number(f0.r, 'f', 4)
            : QStringLiteral("%1, %2, %3").arg(f0.r, 0, 'f', 4).arg(f0.g, 0, 'f', 4).arg(f0.b, 0, 'f', 4));
    m_specularColor->setLinearColor(material.specularColor());
    // The button shows a colour in [0, 1]; a tint above 1 (imported, typed with --set) is said in numbers.
    const glm::dvec3 tint = material.specularColor();
    m_specularColor->setToolTip(tr("%1: %2, %3, %4")
                                    .arg(QString::fromUtf8(infoOf(MaterialProperty::SpecularColor).label))
                                    .arg(tint.r)
                                    .arg(tint.g)
                                    .arg(tint.b));
    select(m_composition, int(material.shading.composition));
    select(m_distribution, int(material.shading.distribution));
    select(m_visibility, int(material.shading.visibility));
    select(m_fresnel, int(material.shading.fresnel));
    select(m_coupling, int(material.shading.coupling));
    m_multiScatter->setChecked(material.shading.multiScatter);
    select(m_alphaMode, int(material.alphaMode));
    m_alphaCutoff->setEnabled(material.alphaMode == AlphaMode::Mask);
    m_doubleSided->setChecked(material.doubleSided);
    m_unlit->setChecked(material.unlit);
    for (const auto& [property, slider] : m_propertySliders)
        slider->setValue(scalarOf(material, property));
    m_clearcoatGroup->setChecked(material.hasClearcoat()); // toggled: the sliders show or hide
    m_sheenGroup->setChecked(material.hasSheen());
    m_sheenColor->setLinearColor(material.sheenColor());
    m_anisotropyGroup->setChecked(material.hasAnisotropy());
    m_iridescenceGroup->setChecked(material.hasIridescence());
}

void MaterialDock::editShading(const QString& undoText, const std::function<void(ShadingModel&)>& change)
{
    Material material = m_document->project().material();
    change(material.shading);
    m_document->setMaterial(material, undoText);
}

void MaterialDock::reloadPresets()
{
    const QString selected = m_presets->currentItem() ? m_presets->currentItem()->text() : QString();
    m_presets->clear();
    int index = 0;
    for (const MaterialPreset& preset : builtinPresets()) {
        auto* item = new QListWidgetItem(QString::fromStdString(preset.displayName), m_presets);
        item->setData(kSwatchKeyRole, QStringLiteral("builtin|") + QString::fromStdString(preset.id));
        m_swatches->requestSwatch(item->data(kSwatchKeyRole).toString(), preset.material, swatchSize());
        item->setData(kPresetRole, index++);
        item->setToolTip(
            tr("Built-in: F0 %1, roughness %2")
                .arg(preset.material.metallic() > 0.5 ? tr("from the base colour (metal)")
                                                      : QString::number(preset.material.dielectricF0()))
                .arg(preset.material.roughness()));
    }
    QStringList problems;
    m_userPresets = UserPresets::load(&problems);
    index = 0;
    for (const UserPreset& preset : m_userPresets) {
        const QString name = QString::fromStdString(preset.preset.displayName);
        const QString where = preset.folder.isEmpty() ? tr("user") : preset.folder;
        auto* item = new QListWidgetItem(
            preset.package ? tr("%1 (%2, with textures)").arg(name, where) : tr("%1 (%2)").arg(name, where),
            m_presets);
        item->setData(kPresetRole, kUserOffset + index++);
        item->setToolTip(preset.path);
        item->setData(kSwatchKeyRole, QStringLiteral("user|") + preset.path);
        m_swatches->requestSwatch(
            item->data(kSwatchKeyRole).toString(), preset.preset.material, swatchSize());
    }
    if (!problems.isEmpty())
        Q_EMIT message(
            tr("Some user presets could not be read: %1").arg(problems.join(QStringLiteral("; "))));
    const auto matches = m_presets->findItems(selected, Qt::MatchExactly);
    if (!matches.isEmpty())
        m_presets->setCurrentItem(matches.first());
    if (m_search)
        filterPresets(m_search->text());
    watchFolders();
    updatePresetButtons();
}

void MaterialDock::updatePresetButtons()
{
    const QListWidgetItem* item = m_presets->currentItem();
    m_apply->setEnabled(item != nullptr);
    // Only the user's own presets can be deleted; an added folder's are read.
    const int index = item ? item->data(kPresetRole).toInt() : -1;
    m_delete->setEnabled(
        index >= kUserOffset && m_userPresets.at(std::size_t(index - kUserOffset)).folder.isEmpty());
}

QMimeData* MaterialDock::presetMimeData(const QListWidgetItem* item) const
{
    if (!item)
        return nullptr;
    const int index = item->data(kPresetRole).toInt();
    const MaterialPreset& preset = index >= kUserOffset
        ? m_userPresets.at(std::size_t(index - kUserOffset)).preset
        : builtinPresets().at(std::size_t(index));
    Material material = preset.material;
    material.name = preset.displayName;
    return materialMimeData(material);
}

bool MaterialDock::applySelectedPreset()
{
    const QListWidgetItem* item = m_presets->currentItem();
    if (!item)
        return false;
    const int index = item->data(kPresetRole).toInt();
    Q_EMIT message(index >= kUserOffset
            ? m_document->applyPreset(m_userPresets.at(std::size_t(index - kUserOffset)).preset)
            : m_document->applyPreset(builtinPresets().at(std::size_t(index))));
    return true;
}

void MaterialDock::askPresetName()
{
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Save As Preset"), tr("Preset name:"),
        QLineEdit::Normal, QString::fromStdString(m_document->project().material().name), &ok);
    if (ok)
        saveCurrentAsPreset(name);
}

bool MaterialDock::saveCurrentAsPreset(const QString& name)
{
    QString error;
    const QString path = UserPresets::save(name, m_document->project().material(), &error);
    if (path.isEmpty()) {
        Q_EMIT message(tr("Could not save the preset: %1").arg(error));
        return false;
    }
    reloadPresets();
    for (int row = 0; row < m_presets->count(); ++row)
        if (m_presets->item(row)->toolTip() == path)
            m_presets->setCurrentRow(row);
    Q_EMIT message(tr("Saved the preset “%1” to %2").arg(name.trimmed(), path));
    return true;
}

void MaterialDock::askExportPackage()
{
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Export Preset Package"), tr("Preset name:"),
        QLineEdit::Normal, QString::fromStdString(m_document->project().material().name), &ok);
    if (!ok)
        return;
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Export Preset Package Into"));
    if (!folder.isEmpty())
        exportCurrentAsPackage(name, folder);
}

void MaterialDock::askImportPackage()
{
    const QString path
        = QFileDialog::getExistingDirectory(this, tr("Import Preset Package (a .facetpreset folder)"));
    if (!path.isEmpty())
        importPackage(path);
}

QString MaterialDock::exportCurrentAsPackage(const QString& name, const QString& folder)
{
    QString error;
    const QString path = UserPresets::exportPackage(name, m_document->project().material(), folder, &error);
    if (path.isEmpty()) {
        Q_EMIT message(tr("Could not export the preset package: %1").arg(error));
        return {};
    }
    Q_EMIT message(
        tr("Exported the preset package “%1” to %2").arg(name.trimmed(), QDir::toNativeSeparators(path)));
    return path;
}

int MaterialDock::pendingSwatches() const
{
    return m_swatches->pending();
}

bool MaterialDock::addPresetFolder(const QString& folder)
{
    QString error;
    if (!UserPresets::addFolder(folder, &error)) {
        Q_EMIT message(error);
        return false;
    }
    reloadPresets();
    Q_EMIT message(tr("Added the presets of %1").arg(QDir::toNativeSeparators(folder)));
    return true;
}

bool MaterialDock::importPackage(const QString& path)
{
    QString error;
    const QString installed = UserPresets::importPackage(path, &error);
    if (installed.isEmpty()) {
        Q_EMIT message(tr("Could not import the preset package: %1").arg(error));
        return false;
    }
    reloadPresets();
    for (int row = 0; row < m_presets->count(); ++row)
        if (m_presets->item(row)->toolTip() == installed)
            m_presets->setCurrentRow(row);
    Q_EMIT message(tr("Imported the preset package %1").arg(QFileInfo(path).fileName()));
    return true;
}

bool MaterialDock::deleteSelectedPreset()
{
    const QListWidgetItem* item = m_presets->currentItem();
    if (!item || item->data(kPresetRole).toInt() < kUserOffset) {
        Q_EMIT message(tr("Only user presets can be deleted"));
        return false;
    }
    const UserPreset& preset = m_userPresets.at(std::size_t(item->data(kPresetRole).toInt() - kUserOffset));
    if (!preset.folder.isEmpty()) {
        Q_EMIT message(tr("“%1” is in the added folder %2: Facet lists it, it does not delete it")
                           .arg(QString::fromStdString(preset.preset.displayName), preset.folder));
        return false;
    }
    QString error;
    if (!UserPresets::remove(preset.path, &error)) {
        Q_EMIT message(tr("Could not delete the preset: %1").arg(error));
        return false;
    }
    Q_EMIT message(tr("Deleted the preset “%1”").arg(QString::fromStdString(preset.preset.displayName)));
    reloadPresets();
    return true;
}

} // namespace facet
