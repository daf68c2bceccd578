#include "ui/docks/MaterialsDock.h"

#include "core/material/MaterialList.h"
#include "core/project/Project.h"
#include "ui/document/Document.h"
#include "ui/document/MaterialTransfer.h"
#include "ui/viewport/SceneController.h"

#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMenu>

#include <QSignalBlocker>
#include <QStringListModel>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace facet {

namespace {

constexpr int kPartColumn = 0;
constexpr int kMaterialColumn = 1;

QString nameOf(const Material& material)
{
    return QString::fromStdString(material.name);
}

QStringList namesOf(const Project& project)
{
    QStringList names;
    names.reserve(qsizetype(project.materials.size()));
    for (const Material& material : project.materials)
        names.append(nameOf(material));
    return names;
}

} // namespace

MaterialsDock::MaterialsDock(Document* document, SceneController* scene, QWidget* parent)
    : QDockWidget(tr("Materials"), parent)
    , m_document(document)
    , m_scene(scene)
    , m_materials(new QListWidget(this))
    , m_newButton(new QToolButton(this))
    , m_duplicateButton(new QToolButton(this))
    , m_deleteButton(new QToolButton(this))
    , m_parts(new QTreeWidget(this))
    , m_assignButton(new QToolButton(this))
    , m_materialNames(new QStringListModel(this))
    , m_partsNote(new QLabel(this))
{
    setObjectName(QStringLiteral("materialsDock"));
    m_materials->setObjectName(QStringLiteral("materialList"));
    m_materials->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_materials->setToolTip(tr("The project's materials: the selected one is edited in the Texture Maps and "
                               "Material panels. Double-click to rename; right-click for more."));
    m_materials->setContextMenuPolicy(Qt::CustomContextMenu);
    // A material dragged onto a part in the viewport gives it that material (ui/document/MaterialTransfer.h).
    makeMaterialDragSource(m_materials, [this](const QListWidgetItem* item) -> QMimeData* {
        const int row = m_materials->row(item);
        const Project& project = m_document->project();
        return row >= 0 && std::size_t(row) < project.materials.size()
            ? materialMimeData(project.materials[std::size_t(row)], row)
            : nullptr;
    });
    connect(m_materials, &QWidget::customContextMenuRequested, this, &MaterialsDock::showMaterialMenu);
    // The list's own keys (while it has focus): Delete, Ctrl+D, Ctrl+Shift+N.
    const auto listAction = [this](const QString& name, const QKeySequence& keys, auto slot) {
        auto* action = new QAction(name, m_materials);
        action->setShortcut(keys);
        action->setShortcutContext(Qt::WidgetShortcut);
        connect(action, &QAction::triggered, this, slot);
        m_materials->addAction(action);
    };
    listAction(
        tr("Delete Material"), QKeySequence::Delete, [this] { deleteMaterial(m_materials->currentRow()); });
    listAction(tr("Duplicate Material"), QKeySequence(tr("Ctrl+D")),
        [this] { duplicateMaterial(m_materials->currentRow()); });
    listAction(tr("New Material"), QKeySequence(tr("Ctrl+Shift+N")), [this] { newMaterial(); });
    const auto button = [this](QToolButton* b, const char* name, const QString& text, const QString& tip) {
        b->setObjectName(QLatin1String(name));
        b->setText(text);
        b->setToolTip(tip);
        b->setAutoRaise(true);
    };
    button(m_newButton, "newMaterialButton", tr("New"),
        tr("A new material after the selected one (Ctrl+Shift+N)"));
    button(m_duplicateButton, "duplicateMaterialButton", tr("Duplicate"),
        tr("A copy of the selected material, maps and all (Ctrl+D)"));
    button(m_deleteButton, "deleteMaterialButton", tr("Delete"),
        tr("Delete the selected material: its parts show the one before it (Delete; Ctrl+Z brings it back)"));
    connect(m_newButton, &QToolButton::clicked, this, &MaterialsDock::newMaterial);
    connect(m_duplicateButton, &QToolButton::clicked, this,
        [this] { duplicateMaterial(m_materials->currentRow()); });
    connect(
        m_deleteButton, &QToolButton::clicked, this, [this] { deleteMaterial(m_materials->currentRow()); });
    // Several parts take one material in one step (Substance Painter's "assign to selection"):
    // select them (Ctrl or Shift), then Assign or the list's context menu.
    button(m_assignButton, "assignToPartsButton", tr("Assign to Selected"),
        tr("Assign a material to every selected part, in one undo step"));
    m_assignButton->setPopupMode(QToolButton::InstantPopup);
    m_assignButton->setMenu(new QMenu(m_assignButton));
    m_assignButton->setEnabled(false);
    connect(m_assignButton->menu(), &QMenu::aboutToShow, this,
        [this] { fillAssignMenu(m_assignButton->menu()); });
    m_parts->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_parts->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_parts, &QWidget::customContextMenuRequested, this, [this](const QPoint& position) {
        if (selectedParts().empty())
            return;
        QMenu menu(this);
        fillAssignMenu(
            menu.addMenu(tr("Assign Material to %n Selected Part(s)", nullptr, int(selectedParts().size()))));
        menu.exec(m_parts->viewport()->mapToGlobal(position));
    });
    connect(m_parts, &QTreeWidget::itemSelectionChanged, this,
        [this] { m_assignButton->setEnabled(!selectedParts().empty()); });
    m_parts->setObjectName(QStringLiteral("partList"));
    m_parts->setColumnCount(2);
    m_parts->setHeaderLabels({tr("Part"), tr("Material")});
    m_parts->setRootIsDecorated(false);
    m_parts->setUniformRowHeights(true);
    m_parts->header()->setSectionResizeMode(kPartColumn, QHeaderView::Stretch);
    // A width of its own, not fitted to the contents: fitting measured every row's combo on each
    // change (a 1 000-part mesh: most of an edit's time).
    m_parts->header()->setSectionResizeMode(kMaterialColumn, QHeaderView::Interactive);
    m_parts->header()->resizeSection(kMaterialColumn, m_parts->fontMetrics().averageCharWidth() * 18 + 32);
    m_parts->header()->setStretchLastSection(false);
    m_parts->setToolTip(tr("The parts of the mesh: tick to show, untick to hide; the material each shows. "
                           "Click a part in the viewport to edit its material."));
    // Room for a few rows of each before the dock scrolls (a dock's first size comes from its
    // content: resizeDocks before the window is shown does not hold).
    m_materials->setMinimumHeight(m_materials->fontMetrics().height() * 5);
    m_parts->setMinimumHeight(m_parts->fontMetrics().height() * 8);
    m_partsNote->setObjectName(QStringLiteral("partsNote"));
    m_partsNote->setWordWrap(true);
    m_partsNote->setText(tr("Click a part in the viewport to edit its material."));

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->addWidget(new QLabel(tr("<b>Materials</b>"), content));
    layout->addWidget(m_materials, 1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_newButton);
    buttons->addWidget(m_duplicateButton);
    buttons->addWidget(m_deleteButton);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    layout->addWidget(new QLabel(tr("<b>Parts</b>"), content));
    layout->addWidget(m_parts, 2);
    auto* partButtons = new QHBoxLayout;
    partButtons->addWidget(m_assignButton);
    partButtons->addStretch(1);
    layout->addLayout(partButtons);
    layout->addWidget(m_partsNote);
    setWidget(content);

    connect(m_materials, &QListWidget::currentRowChanged, this, [this](int row) {
        if (!m_updating && row >= 0)
            m_document->setCurrentMaterial(row);
    });
    connect(m_materials, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        if (!m_updating)
            renameMaterial(m_materials->row(item), item->text());
    });
    connect(m_parts, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (m_updating || column != kPartColumn)
            return;
        setPartVisible(m_parts->indexOfTopLevelItem(item), item->checkState(kPartColumn) == Qt::Checked);
    });
    connect(m_parts, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (m_updating || !item)
            return;
        const int part = m_parts->indexOfTopLevelItem(item);
        if (part >= 0)
            m_document->setCurrentMaterial(m_document->project().materialOfPart(std::size_t(part)));
    });
    connect(m_document, &Document::changed, this, &MaterialsDock::onDocumentChanged);
    connect(m_scene, &SceneController::sceneChanged, this, &MaterialsDock::onSceneChanged);
    refreshMaterials();
    refreshParts(true);
}

MaterialsDock::~MaterialsDock() = default;

QComboBox* MaterialsDock::partMaterialCombo(int part) const
{
    QTreeWidgetItem* item = m_parts->topLevelItem(part);
    return item ? qobject_cast<QComboBox*>(m_parts->itemWidget(item, kMaterialColumn)) : nullptr;
}

int MaterialsDock::partCount() const
{
    const std::shared_ptr<const Mesh>& mesh = m_scene->assets().mesh;
    if (!mesh)
        return 0;
    // A mesh without sub-meshes is drawn as one part (Project::materialOfPart(0)).
    return int(std::max<std::size_t>(mesh->subMeshes.size(), 1));
}

QString MaterialsDock::partName(int part) const
{
    const std::shared_ptr<const Mesh>& mesh = m_scene->assets().mesh;
    std::string name;
    if (mesh && std::size_t(part) < mesh->subMeshes.size())
        name = mesh->subMeshes[std::size_t(part)].name;
    else if (mesh && mesh->subMeshes.empty())
        name = mesh->name;
    return name.empty() ? tr("Part %1").arg(part + 1) : QString::fromStdString(name);
}

void MaterialsDock::onDocumentChanged(DocumentChanges changes)
{
    // Names (MaterialFactors), the number of materials and the selection show in both lists; a
    // roughness drag also reports MaterialFactors, and then only texts are compared.
    if (changes
        & (DocumentChanges(DocumentChange::MaterialFactors) | DocumentChange::CurrentMaterial
            | DocumentChange::Parts | DocumentChange::Mesh))
        refreshMaterials();
    if (changes
        & (DocumentChanges(DocumentChange::MaterialFactors) | DocumentChange::Parts | DocumentChange::Mesh))
        refreshParts(m_scene->assets().meshKey != m_shownMeshKey);
}

void MaterialsDock::onSceneChanged()
{
    // The mesh is loaded by SceneController (possibly after the document changed): new parts.
    if (m_scene->assets().meshKey != m_shownMeshKey) {
        refreshParts(true);
        refreshMaterials(); // how many parts show each material
    }
}

void MaterialsDock::refreshMaterials()
{
    const Project& project = m_document->project();
    m_updating = true;
    if (m_materials->count() != int(project.materials.size())) {
        m_materials->clear();
        for (std::size_t m = 0; m < project.materials.size(); ++m) {
            auto* item = new QListWidgetItem(m_materials);
            item->setFlags(item->flags() | Qt::ItemIsEditable);
        }
    }
    std::vector<int> users(project.materials.size(), 0);
    const std::size_t parts = std::size_t(std::max(partCount(), 0));
    for (std::size_t p = 0; p < parts; ++p)
        ++users[std::size_t(project.materialOfPart(p))];
    for (int m = 0; m < m_materials->count(); ++m) {
        QListWidgetItem* item = m_materials->item(m);
        const QString name = nameOf(project.materials[std::size_t(m)]);
        if (item->text() != name)
            item->setText(name);
        const int n = users[std::size_t(m)];
        item->setToolTip(
            n == 1 ? tr("%1: shown on 1 part").arg(name) : tr("%1: shown on %2 parts").arg(name).arg(n));
    }
    m_materials->setCurrentRow(project.currentMaterial);
    m_deleteButton->setEnabled(project.materials.size() > 1);
    m_updating = false;
}

void MaterialsDock::showMaterialMenu(const QPoint& position)
{
    QListWidgetItem* item = m_materials->itemAt(position);
    const int row = item ? m_materials->row(item) : -1;
    QMenu menu(this);
    menu.addAction(tr("New Material"), this, &MaterialsDock::newMaterial);
    if (row >= 0) {
        menu.addAction(tr("Duplicate"), this, [this, row] { duplicateMaterial(row); });
        menu.addAction(tr("Rename"), this, [this, item] { m_materials->editItem(item); });
        QAction* remove = menu.addAction(tr("Delete"), this, [this, row] { deleteMaterial(row); });
        remove->setEnabled(m_document->project().materials.size() > 1);
    }
    menu.exec(m_materials->viewport()->mapToGlobal(position));
}

void MaterialsDock::applyListEdit(const std::optional<Project>& after, const std::string& problem,
    const QString& undoText, const QString& done)
{
    if (!after) {
        Q_EMIT message(tr("%1: %2").arg(undoText, QString::fromStdString(problem)));
        return;
    }
    m_document->setProject(*after, undoText);
    Q_EMIT message(done);
}

void MaterialsDock::newMaterial()
{
    const Project& project = m_document->project();
    Material material;
    material.name = tr("Material").toStdString();
    std::string problem;
    const std::optional<Project> after
        = withMaterialInserted(project, project.currentMaterial + 1, material, &problem);
    applyListEdit(after, problem, tr("New Material"),
        after ? tr("New material “%1”").arg(nameOf(after->material())) : QString());
}

void MaterialsDock::duplicateMaterial(int material)
{
    std::string problem;
    const std::optional<Project> after = withMaterialDuplicated(m_document->project(), material, &problem);
    applyListEdit(after, problem, tr("Duplicate Material"),
        after ? tr("“%1” is a copy of “%2”")
                    .arg(nameOf(after->material()),
                        nameOf(m_document->project().materials[std::size_t(material)]))
              : QString());
}

void MaterialsDock::deleteMaterial(int material)
{
    const Project& before = m_document->project();
    std::string problem;
    const std::optional<Project> after = withMaterialRemoved(before, material, &problem);
    QString done;
    if (after) {
        int parts = 0;
        for (int p = 0; p < partCount(); ++p)
            parts += before.materialOfPart(std::size_t(p)) == material ? 1 : 0;
        const QString name = nameOf(before.materials[std::size_t(material)]);
        const QString shows = nameOf(after->material());
        done = parts == 0 ? tr("Deleted “%1” (Ctrl+Z brings it back)").arg(name)
            : parts == 1 ? tr("Deleted “%1”: its part shows “%2” (Ctrl+Z brings it back)").arg(name, shows)
                         : tr("Deleted “%1”: its %2 parts show “%3” (Ctrl+Z brings it back)")
                               .arg(name)
                               .arg(parts)
                               .arg(shows);
    }
    applyListEdit(after, problem, tr("Delete Material"), done);
}

void MaterialsDock::refreshParts(bool rebuild)
{
    const Project& project = m_document->project();
    const int count = partCount();
    m_updating = true;
    // The names, once for every row (a reset of the shared model: each combo's index is set below).
    if (const QStringList names = namesOf(project); names != m_materialNames->stringList())
        m_materialNames->setStringList(names);
    if (rebuild || m_parts->topLevelItemCount() != count) {
        m_parts->clear();
        for (int part = 0; part < count; ++part) {
            auto* item = new QTreeWidgetItem(m_parts);
            item->setText(kPartColumn, partName(part));
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            // Every row's combo shows the one list of names (issue 30: 1 000 combos of 500 entries each
            // froze the window for 13 s on opening and seconds on every edit); its width does not
            // depend on the names, so no row measures 500 of them.
            auto* combo = new QComboBox(m_parts);
            combo->setObjectName(QStringLiteral("partMaterial_%1").arg(part));
            combo->setModel(m_materialNames);
            combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
            combo->setMinimumContentsLength(12);
            connect(combo, &QComboBox::activated, this, [this, part](int material) {
                if (!m_updating)
                    setPartMaterial(part, material);
            });
            m_parts->setItemWidget(item, kMaterialColumn, combo);
        }
        m_shownMeshKey = m_scene->assets().meshKey;
    }
    for (int part = 0; part < count; ++part) {
        QTreeWidgetItem* item = m_parts->topLevelItem(part);
        item->setCheckState(
            kPartColumn, project.isPartVisible(std::size_t(part)) ? Qt::Checked : Qt::Unchecked);
        item->setToolTip(kPartColumn,
            project.isPartVisible(std::size_t(part)) ? tr("Shown: untick to hide it")
                                                     : tr("Hidden: tick to show it"));
        QComboBox* combo = partMaterialCombo(part);
        const int material = project.materialOfPart(std::size_t(part));
        if (combo->currentIndex() != material) {
            const QSignalBlocker blocker(combo);
            combo->setCurrentIndex(material);
        }
    }
    m_updating = false;
}

std::vector<MeshPart> MaterialsDock::partsForEditing() const
{
    std::vector<MeshPart> parts = m_document->project().parts;
    for (int part = int(parts.size()); part < partCount(); ++part)
        parts.push_back(MeshPart {partName(part).toStdString(), 0, true});
    return parts;
}

void MaterialsDock::renameMaterial(int material, const QString& name)
{
    const Project& project = m_document->project();
    if (material < 0 || std::size_t(material) >= project.materials.size())
        return;
    const std::string trimmed = name.trimmed().toStdString();
    if (trimmed.empty()) {
        Q_EMIT message(tr("A material needs a name; “%1” kept its own")
                           .arg(nameOf(project.materials[std::size_t(material)])));
        refreshMaterials();
        return;
    }
    if (trimmed == project.materials[std::size_t(material)].name)
        return;
    Project after = project;
    after.materials[std::size_t(material)].name = trimmed;
    m_document->setProject(after, tr("Rename Material"));
}

void MaterialsDock::setPartVisible(int part, bool visible)
{
    std::vector<MeshPart> parts = partsForEditing();
    if (part < 0 || part >= partCount() || std::size_t(part) >= parts.size())
        return;
    parts[std::size_t(part)].visible = visible;
    const QString name = partName(part);
    m_document->setParts(parts, visible ? tr("Show %1").arg(name) : tr("Hide %1").arg(name));
}

void MaterialsDock::setPartMaterial(int part, int material)
{
    const Project& project = m_document->project();
    std::vector<MeshPart> parts = partsForEditing();
    if (part < 0 || part >= partCount() || std::size_t(part) >= parts.size() || material < 0
        || std::size_t(material) >= project.materials.size())
        return;
    parts[std::size_t(part)].material = material;
    m_document->setParts(
        parts, tr("Assign %1 to %2").arg(nameOf(project.materials[std::size_t(material)]), partName(part)));
}

std::vector<int> MaterialsDock::selectedParts() const
{
    std::vector<int> parts;
    for (QTreeWidgetItem* item : m_parts->selectedItems())
        parts.push_back(m_parts->indexOfTopLevelItem(item));
    std::sort(parts.begin(), parts.end());
    return parts;
}

void MaterialsDock::fillAssignMenu(QMenu* menu)
{
    menu->clear();
    const Project& project = m_document->project();
    for (std::size_t material = 0; material < project.materials.size(); ++material) {
        QAction* action = menu->addAction(nameOf(project.materials[material]));
        action->setObjectName(QStringLiteral("assignMaterial_%1").arg(material));
        if (int(material) == project.currentMaterial)
            action->setText(tr("%1 (current)").arg(action->text()));
        connect(action, &QAction::triggered, this,
            [this, material] { assignMaterialToParts(int(material), selectedParts()); });
    }
}

void MaterialsDock::assignMaterialToParts(int material, const std::vector<int>& parts)
{
    const Project& project = m_document->project();
    if (material < 0 || std::size_t(material) >= project.materials.size())
        return;
    std::vector<MeshPart> edited = partsForEditing();
    int changed = 0;
    for (const int part : parts)
        if (part >= 0 && part < partCount() && std::size_t(part) < edited.size()
            && edited[std::size_t(part)].material != material) {
            edited[std::size_t(part)].material = material;
            ++changed;
        }
    const QString name = nameOf(project.materials[std::size_t(material)]);
    if (changed == 0) {
        Q_EMIT message(tr("The selected parts already show %1").arg(name));
        return;
    }
    const QString what = changed == 1 ? tr("Assign %1 to a part").arg(name)
                                      : tr("Assign %1 to %2 parts").arg(name).arg(changed);
    m_document->setParts(edited, what);
    Q_EMIT message(changed == 1 ? tr("Assigned %1 to 1 part").arg(name)
                                : tr("Assigned %1 to %2 parts").arg(name).arg(changed));
}

void MaterialsDock::selectPart(int part, bool extend)
{
    QTreeWidgetItem* item = m_parts->topLevelItem(part);
    if (!item)
        return;
    m_updating = true;
    if (extend) {
        const bool selected = !item->isSelected();
        m_parts->setCurrentItem(item, 0, QItemSelectionModel::NoUpdate);
        item->setSelected(selected);
        const int count = int(selectedParts().size());
        Q_EMIT message(count == 1 ? tr("1 part selected") : tr("%1 parts selected").arg(count));
    } else {
        m_parts->setCurrentItem(item);
    }
    m_parts->scrollToItem(item);
    m_updating = false;
}

} // namespace facet
