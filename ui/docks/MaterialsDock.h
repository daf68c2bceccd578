#pragma once
// The Materials dock: the project's materials and the parts of the mesh.
//
// - Materials: one row per material, the current one selected. Choosing a row makes it the one
//   the Texture Maps and Material docks edit (Document::setCurrentMaterial: a selection, not an
//   undo step). Double-click (or F2) renames it: one undo step "Rename Material". New, Duplicate
//   and Delete (the buttons under the list, its context menu, Ctrl+Shift+N, Ctrl+D and Delete in
//   the list) are one undo step each (core/material/MaterialList.h: every part and A/B's B keep showing
//   what they showed; a deleted material's parts show the one before it).
// - Parts: one row per part of the loaded mesh (the sub-meshes of SceneController's mesh, in
//   order, named as the file names them), with a check box that shows or hides it and the
//   material it shows (a combo of the project's materials). Each edit is one undo step through
//   Document::setParts; the project's part list is extended to the mesh's part count first (a part
//   without an entry shows material 0 and is visible, core/project/Project.h MeshPart). Choosing a part's
//   row makes its material current, as clicking it in the viewport does (ui/viewport/PartPicker.h), and a
//   click in the viewport selects its row here.

#include "ui/document/DocumentChanges.h"

#include <QDockWidget>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QMenu;
class QToolButton;
class QListWidget;
class QListWidgetItem;
class QStringListModel;
class QTreeWidget;
class QTreeWidgetItem;

namespace facet {

class Document;
class SceneController;
struct MeshPart;
struct Project;

class MaterialsDock : public QDockWidget {
    Q_OBJECT
public:
    MaterialsDock(Document* document, SceneController* scene, QWidget* parent = nullptr);
    ~MaterialsDock() override;

    QListWidget* materialList() const { return m_materials; }
    QTreeWidget* partList() const { return m_parts; }
    // The material combo of part `part`'s row (null when there is no such row).
    QComboBox* partMaterialCombo(int part) const;
    // How many parts the loaded mesh has (rows in the parts list).
    int partCount() const;

    // The edits the rows make (tests call them too). Each is one undo step; out of range: ignored.
    void renameMaterial(int material, const QString& name);
    void newMaterial();
    void duplicateMaterial(int material);
    void deleteMaterial(int material);
    void setPartVisible(int part, bool visible);
    void setPartMaterial(int part, int material);
    // Selects `part`'s row without editing anything (a click in the viewport picked it); `extend`
    // (a Ctrl-click) adds the row to the selection, or takes a selected one out.
    void selectPart(int part, bool extend = false);
    // The parts whose rows are selected (Ctrl- and Shift-click select several), in order.
    std::vector<int> selectedParts() const;
    // `material` on every part of `parts` that shows another, one undo step ("Assign Red to 3
    // parts"); the status bar says what changed. The Assign to Selected button's menu and the
    // parts list's context menu call it with the selected parts.
    void assignMaterialToParts(int material, const std::vector<int>& parts);
    QToolButton* assignToPartsButton() const { return m_assignButton; }

Q_SIGNALS:
    void message(const QString& text);

private:
    void onDocumentChanged(DocumentChanges changes);
    void onSceneChanged();
    void refreshMaterials();
    void showMaterialMenu(const QPoint& position);
    // One action per material, each assigning it to the selected parts.
    void fillAssignMenu(QMenu* menu);
    // Applies an edit of the material list (core/material/MaterialList.h) as one undo step, or says why not.
    void applyListEdit(const std::optional<Project>& after, const std::string& problem,
        const QString& undoText, const QString& done);
    void refreshParts(bool rebuild);
    // The project's parts, one entry per part of the loaded mesh at least (MeshPart's defaults).
    std::vector<MeshPart> partsForEditing() const;
    QString partName(int part) const;

    Document* m_document;
    SceneController* m_scene;
    QListWidget* m_materials;
    QToolButton* m_newButton;
    QToolButton* m_duplicateButton;
    QToolButton* m_deleteButton;
    QTreeWidget* m_parts;
    QToolButton* m_assignButton;
    QStringListModel* m_materialNames; // every part's combo shows this one model
    QLabel* m_partsNote;
    std::uint64_t m_shownMeshKey = 0;
    bool m_updating = false; // rows being filled from the document: their signals are not edits
};

} // namespace facet
