#pragma once
// Materials moved between places as data (docs/app.md "Materials"): the clipboard's Copy / Paste
// Material, and a material or preset dragged onto a part of the mesh in the viewport (Marmoset
// Toolbag's drag from its library). Both carry the material as a material object of the project
// format (texture paths absolute) under kMaterialMime and as text; a drag of one of the project's
// own materials also carries its index, so that dropping it assigns that material instead of
// adding a copy.

#include "core/material/Material.h"

#include <QObject>
#include <QPointF>

#include <functional>
#include <optional>

class QListWidget;
class QListWidgetItem;
class QMimeData;
class QWidget;

namespace facet {

class Document;
class PartPicker;

inline constexpr const char* kMaterialMime = "application/x-facet-material+json";
inline constexpr const char* kMaterialIndexMime = "application/x-facet-material-index";

// The material as MIME data; `projectIndex`: one of the project's materials.
QMimeData* materialMimeData(const Material& material, std::optional<int> projectIndex = std::nullopt);
struct TransferredMaterial {
    Material material;
    std::optional<int> projectIndex;
};
// The material `mime` carries (also as text, as a clipboard from another program holds it);
// nullopt with *error (empty when it carries nothing that looks like a material).
std::optional<TransferredMaterial> materialFromMimeData(const QMimeData* mime, std::string* error = nullptr);

// Lets `list`'s items be dragged out (a left-button drag past the platform's drag distance):
// `mime` makes the data of the item pressed (null: nothing to drag). The list keeps its own
// click, double-click and selection behaviour.
void makeMaterialDragSource(QListWidget* list, std::function<QMimeData*(const QListWidgetItem*)> mime);

// Drops of a material on the viewport: onto the part under the cursor. A project material is
// assigned to the part; a preset (or a material from another window) is added to the project
// (its name made unique) and assigned, in one undo step ("Drop Gold onto Visor"). A drop that
// misses the mesh changes nothing and says so. Install after the file-drop handler: it sees drags
// first and leaves those without a material to it.
class MaterialDropHandler : public QObject {
    Q_OBJECT
public:
    MaterialDropHandler(Document* document, PartPicker* picker, QWidget* viewport, QObject* parent = nullptr);

    // What a drop of `mime` at `position` (viewport coordinates) does; false when it did nothing
    // (the status bar says why). Tests call it; a drop event comes here.
    bool dropMaterial(const QMimeData* mime, const QPointF& position);

Q_SIGNALS:
    void message(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    Document* m_document;
    PartPicker* m_picker;
    QWidget* m_viewport;
};

} // namespace facet
