#pragma once
// One material map in the Texture maps dock: a thumbnail, the file's name and resolution,
// Open… / Clear, the factor used without a file (or multiplying it), and the per-map options:
// channel (packed textures), colour space, invert (a smoothness map as roughness), the normal
// map's strength and DirectX green flip. Base colour and emissive take a colour (the emissive one
// also its strength, Material::emissiveStrength, on a logarithmic slider); the other slots a number. An image
// file dropped on it becomes its texture; a folder or several files go to the dock (filesDropped) to be
// assigned by name. Right-click: Copy Map, Paste Map, Paste Value. Every edit is an undo step through the
// Document; a drag of the factor slider is one step.

#include "core/material/Material.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;

namespace facet {

class ColorButton;
class MapInspectorDialog;
class Document;
class ValueSlider;

class MapSlotWidget : public QWidget {
    Q_OBJECT
public:
    MapSlotWidget(Document* document, MapSlot slot, QWidget* parent = nullptr);

    MapSlot slot() const { return m_slot; }
    // "Base colour", "Normal", ...
    static QString title(MapSlot slot);
    // How a map reads its file, for messages: "" for a plain single map, else e.g. " (ORM, blue)",
    // " (Unity mask map, alpha, inverted)", " (inverted)", " (DirectX)".
    static QString readNote(
        MapSlot slot, MapChannel channel, bool invert, bool flipGreen, const QString& convention);

    // Shows the document's state of this map (no edit).
    void refresh();
    // The thumbnail of the current file (null image: none / unreadable; `error` then says why).
    void setThumbnail(const QImage& image, QSize sourceSize, const QString& error);
    // Makes `path` this map's texture (one undo step), reading the channel its name's packing
    // convention gives this slot (core/material/MapNaming.h mapReadFor: an ORM on metallic reads blue).
    // False with a message for a file that is not an image Facet reads. Open… and a drop of one
    // file come here.
    bool assignFile(const QString& path);
    void clearFile();
    // The slot's context menu: Copy Map puts this map (file, how it is read, factor) on the
    // clipboard; Paste Map makes a copied map this slot's (core/material/MaterialList.h pastedMap: across
    // kinds of slot, what this one cannot have is left out); Paste Value takes only the factor,
    // between slots of one kind. Each paste is one undo step; false (with a message) when the
    // clipboard holds no map or the value does not fit.
    void copyMap();
    bool pasteMap();
    bool pasteValue();
    // Inspect Map… (the context menu, with a file): the map's channels, what each feeds and their
    // histograms (ui/dialogs/MapInspectorDialog), in a window of its own that closes itself. Null, with a
    // message, when the file cannot be read or the slot has none.
    MapInspectorDialog* inspectMap();

    ValueSlider* factorSlider() const { return m_factor; } // null for base colour and emissive
    ColorButton* colorButton() const { return m_color; } // base colour and emissive only
    ValueSlider* strengthSlider() const { return m_strength; } // emissive only
    QLabel* fileLabel() const { return m_fileLabel; }

Q_SIGNALS:
    // For the status bar: what happened, or why a drop or a file was refused (naming the file).
    void message(const QString& text);
    // A folder or several files were dropped: assign them by name (the dock does).
    void filesDropped(const QStringList& paths);

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;

private:
    void editMap(const MaterialMap& map, const QString& undoText, int mergeId = 0);
    void openFile();

    Document* m_document;
    MapSlot m_slot;
    QLabel* m_thumbnail;
    QLabel* m_fileLabel;
    QPushButton* m_clear;
    ValueSlider* m_factor = nullptr;
    ColorButton* m_color = nullptr;
    ValueSlider* m_strength = nullptr; // emissive: Material::emissiveStrength
    QComboBox* m_channel = nullptr;
    QComboBox* m_colorSpace = nullptr;
    QCheckBox* m_invert = nullptr;
    QCheckBox* m_flipGreen = nullptr;
    QComboBox* m_texCoord = nullptr; // which UV set
    QComboBox* m_wrap = nullptr; // the sampler's wraps (both axes; a file's mixed pair shown as such)
    QSize m_sourceSize;
};

} // namespace facet
