#pragma once
// The undo command of every Document edit (Tiled's ChangeValue): a snapshot of the undoable part
// of the project before and after. A project is a few kilobytes of values, so snapshots are simpler
// and safer than one command class per field, and undo restores exactly what was there.
// What each undo and redo reports (Document::changed) is worked out by comparing the two snapshots
// (changesBetween, ui/document/DocumentChanges.h): a command never says what it changed, so it cannot
// misreport it, and the comparison costs microseconds (tests/bench/document_changes).
//
// Merging: while Document::beginInteractiveEdit() ... endInteractiveEdit() is open, a command with
// the same non-zero merge id as the top command of the same interaction replaces that command's
// "after" (one slider drag = one step); a merge that lands back on "before" makes the command
// obsolete (QUndoCommand::setObsolete), so a drag that ends where it began leaves no step.

#include "core/project/Project.h"

#include <QUndoCommand>

namespace facet {

class Document;

// Merge ids the panels use; any other positive number works too (ids from kFirstFree up are free).
namespace MergeId {
enum : int {
    None = 0, // never merges
    BaseColor = 1,
    Metallic,
    Roughness,
    Occlusion,
    NormalStrength,
    UvTransform,
    EnvironmentRotation,
    EnvironmentIntensity,
    Exposure,
    Gamma,
    BackgroundColor,
    BackgroundBlur,
    LightColor,
    LightIntensity,
    LightKelvin,
    LightDirection,
    LightPosition,
    LightRange,
    LightCone,
    EmissiveStrength,
    // A slider made from a row of the material property registry (core/material/
    // MaterialProperties): MaterialProperty0 + int(MaterialProperty).
    MaterialProperty0 = 500,
    kFirstFree = 1000,
};
} // namespace MergeId

class ChangeProjectCommand : public QUndoCommand {
public:
    // `before` and `after` are full projects; their cameras are ignored (camera moves are not undoable).
    ChangeProjectCommand(Document* document, Project before, Project after, const QString& text, int mergeId);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* m_document;
    Project m_before;
    Project m_after;
    int m_mergeId;
    int m_interactionSerial; // the interactive edit this command was made in; 0: none
};

} // namespace facet
