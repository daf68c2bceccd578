#include "ui/document/DocumentCommands.h"

#include "ui/document/Document.h"

#include <utility>

namespace facet {

ChangeProjectCommand::ChangeProjectCommand(
    Document* document, Project before, Project after, const QString& text, int mergeId)
    : QUndoCommand(text)
    , m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
    , m_mergeId(mergeId)
    , m_interactionSerial(document->interactionSerial())
{
}

void ChangeProjectCommand::undo()
{
    m_document->applyUndoableState(m_before);
}

void ChangeProjectCommand::redo()
{
    m_document->applyUndoableState(m_after);
}

int ChangeProjectCommand::id() const
{
    // -1 tells QUndoStack never to try merging.
    return m_mergeId > 0 && m_interactionSerial != 0 ? m_mergeId : -1;
}

bool ChangeProjectCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const ChangeProjectCommand*>(other);
    if (!next || next->m_mergeId != m_mergeId || next->m_interactionSerial != m_interactionSerial)
        return false;
    // The interaction is still the open one: a finished drag never absorbs a later edit.
    if (m_document->interactionSerial() != m_interactionSerial)
        return false;
    m_after = next->m_after;
    Project before = m_before;
    before.camera = m_after.camera;
    setObsolete(before == m_after);
    return true;
}

} // namespace facet
