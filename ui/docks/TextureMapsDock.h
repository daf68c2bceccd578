#pragma once
// The Texture maps dock: one MapSlotWidget per material map, a UV transform for the whole set,
// and the texture set as a whole: dropping a folder or several files (anywhere on the dock) or
// Assign Folder assigns maps by name (core/material/MapNaming.h) in one undo step, replacing the whole set,
// and says what it assigned and cleared. The note is cleared when another project replaces the
// document. Texture files that change on disk are reloaded (QFileSystemWatcher): that map only.
// It edits the project's current material (chosen in the Materials dock or by clicking a part in
// the viewport) and says which one that is.

#include "core/material/Material.h"
#include "ui/document/DocumentChanges.h"

#include <QDockWidget>
#include <QHash>

#include <array>

class QFileSystemWatcher;
class QCheckBox;
class QLabel;
class QTimer;

namespace facet {

class Document;
class MapSlotWidget;
class ThumbnailLoader;
class ValueSlider;

class TextureMapsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit TextureMapsDock(Document* document, QWidget* parent = nullptr);
    ~TextureMapsDock() override;

    MapSlotWidget* slotWidget(MapSlot slot) const { return m_slots[std::size_t(slot)]; }
    // The box holding a lobe's slots (the clear coat's, the sheen's, the specular layer's), hidden
    // while the lobe is off (Material::hasLobe; the specular layer's always shown: its defaults are
    // the core's); null for the core slots.
    QWidget* lobeSlots(MaterialLobe lobe) const { return m_lobeSlots[std::size_t(lobe)]; }
    // Assigns the files (folders are listed) by name as one undo step "Assign Maps" and returns
    // the message it also emits: what went where, what was cleared and what was not used. A
    // folder or several files is a texture set and replaces the whole set (core/material/MapNaming.h
    // withTextureSet: slots it does not fill lose their texture); one file only adds its maps.
    QString assignFiles(const QStringList& paths);
    // The last assignment message (also in the dock); empty after New/Open/recovery.
    QString lastMessage() const;
    // "Material: Visor (2 of 5)": which of the project's materials the dock edits.
    QLabel* materialLabel() const { return m_materialLabel; }
    // Thumbnail jobs still running (tests wait for 0).
    int pendingThumbnails() const;

Q_SIGNALS:
    void message(const QString& text);

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void onDocumentChanged(DocumentChanges changes);
    void refreshThumbnails(bool force);
    void watchFiles();
    void onFileChanged(const QString& path);
    void onFolderChanged(const QString& folder);
    void reloadChangedFiles();
    void assignFolder();
    void report(const QString& text);

    Document* m_document;
    std::array<MapSlotWidget*, kMapSlotCount> m_slots {};
    // Each layered lobe's slots, under their heading, by MaterialLobe: shown while the lobe is on
    // (null for the core).
    std::array<QWidget*, std::size_t(MaterialLobe::Iridescence) + 1> m_lobeSlots {}; // by MaterialLobe
    ThumbnailLoader* m_thumbnails;
    QFileSystemWatcher* m_watcher;
    QTimer* m_reloadTimer;
    QStringList m_changedFiles;
    QStringList m_wantedFiles; // the current material's map files, existing or not
    QLabel* m_messageLabel;
    int m_reportedAt = -1; // the undo index after the step m_messageLabel reports (-1: none)
    QLabel* m_materialLabel; // which material the dock edits
    std::array<QString, kMapSlotCount> m_thumbnailKeys; // what each slot's thumbnail shows
    ValueSlider* m_uvScale; // U
    ValueSlider* m_uvScaleV;
    QCheckBox* m_uvScaleLinked;
    ValueSlider* m_uvOffsetU;
    ValueSlider* m_uvOffsetV;
    ValueSlider* m_uvRotation;
};

} // namespace facet
