#pragma once
// The View dock: the mesh (a built-in primitive or an imported file), the camera's field of view
// and Reset Camera, exposure, the display transform (one of Facet's tone mappers with its
// display encoding, or an OCIO display/view from core/image/ColorManagement), the renderer's debug
// views, MSAA, and the frame statistics (GL version and renderer, frame time, IBL precompute).
// Edits are undo steps except the field of view (camera moves are not undoable).

#include "ui/document/DocumentChanges.h"

#include "core/project/Project.h"

#include <QDockWidget>

#include <functional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace facet {

class Document;
class ValueSlider;
struct GLInfo;
struct ViewportFrameStats;

class ViewDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ViewDock(Document* document, QWidget* parent = nullptr);
    ~ViewDock() override;

    ValueSlider* exposureSlider() const { return m_exposure; }
    QComboBox* debugViewCombo() const { return m_debugView; }
    QComboBox* meshCombo() const { return m_mesh; }
    QComboBox* toneMapperCombo() const { return m_toneMapper; }
    // Sets the mesh to a file (one undo step); a message when it does not exist.
    bool importMesh(const QString& path);

public Q_SLOTS:
    void showGLInfo(const facet::GLInfo& info);
    void showFrameStats(const facet::ViewportFrameStats& stats);

Q_SIGNALS:
    void message(const QString& text);
    void resetCameraRequested();

private:
    void onDocumentChanged(DocumentChanges changes);
    void editView(const QString& undoText, int mergeId, const std::function<void(ViewSettings&)>& change);
    void fillOcioViews(const QString& display);

    Document* m_document;
    QComboBox* m_mesh;
    ValueSlider* m_fov;
    ValueSlider* m_exposure;
    QComboBox* m_toneMapper;
    QComboBox* m_encoding;
    ValueSlider* m_gamma;
    QComboBox* m_ocioDisplay;
    QComboBox* m_ocioView;
    QComboBox* m_debugView;
    QDoubleSpinBox* m_texelDensity; // the texel-density view's target
    QComboBox* m_msaa;
    QLabel* m_glLabel;
    QLabel* m_frameLabel;
    QLabel* m_iblLabel;
    QString m_ocioProblem;
};

} // namespace facet
