#include "ui/docks/ViewDock.h"

#include "core/image/ColorManagement.h"
#include "core/mesh/MeshPrimitives.h"
#include "render/GLInfo.h"
#include "render/ShaderVariant.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"
#include "ui/viewport/ViewportRenderer.h"
#include "ui/widgets/ValueSlider.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace facet {

namespace {

const QString kImportItem = QStringLiteral("\x01import");
// The tone-mapper combo's entry for an OCIO display/view.
constexpr int kOcioEntry = -1;

void selectData(QComboBox* combo, const QVariant& value)
{
    const QSignalBlocker blocker(combo);
    combo->setCurrentIndex(combo->findData(value));
}

} // namespace

ViewDock::ViewDock(Document* document, QWidget* parent)
    : QDockWidget(tr("View"), parent)
    , m_document(document)
    , m_mesh(new QComboBox(this))
    , m_fov(new ValueSlider(10.0, 120.0, 1, this))
    , m_exposure(new ValueSlider(-10.0, 10.0, 2, this))
    , m_toneMapper(new QComboBox(this))
    , m_encoding(new QComboBox(this))
    , m_gamma(new ValueSlider(1.0, 3.0, 2, this))
    , m_ocioDisplay(new QComboBox(this))
    , m_ocioView(new QComboBox(this))
    , m_debugView(new QComboBox(this))
    , m_texelDensity(new QDoubleSpinBox(this))
    , m_msaa(new QComboBox(this))
    , m_glLabel(new QLabel(tr("OpenGL: not initialised yet"), this))
    , m_frameLabel(new QLabel(this))
    , m_iblLabel(new QLabel(this))
{
    setObjectName(QStringLiteral("viewDock"));
    m_mesh->setObjectName(QStringLiteral("meshCombo"));
    for (std::string_view name : primitiveNames())
        m_mesh->addItem(QString::fromLatin1(name.data(), qsizetype(name.size())),
            QString::fromLatin1(name.data(), qsizetype(name.size())));
    m_mesh->insertSeparator(m_mesh->count());
    m_mesh->addItem(tr("Import Mesh…"), kImportItem);
    m_fov->setObjectName(QStringLiteral("fovSlider"));
    m_fov->setSuffix(QStringLiteral("°"));
    m_fov->setToolTip(tr("Vertical field of view (camera changes are not undo steps)"));
    m_exposure->setObjectName(QStringLiteral("exposureSlider"));
    m_exposure->setSuffix(tr(" EV"));
    m_toneMapper->setObjectName(QStringLiteral("toneMapperCombo"));
    const std::pair<ToneMapper, QString> mappers[]
        = {{ToneMapper::KhronosNeutral, tr("Khronos PBR Neutral")}, {ToneMapper::Aces, tr("ACES (Hill)")},
            {ToneMapper::AgX, tr("AgX")}, {ToneMapper::Reinhard, tr("Reinhard")},
            {ToneMapper::Exposure, tr("Exposure (1 - e^-x)")}, {ToneMapper::None, tr("None (clip)")}};
    for (const auto& [mapper, text] : mappers)
        m_toneMapper->addItem(text, int(mapper));
    m_encoding->setObjectName(QStringLiteral("displayEncodingCombo"));
    m_encoding->addItem(tr("sRGB"), int(DisplayEncoding::SRGB));
    m_encoding->addItem(tr("Gamma"), int(DisplayEncoding::Gamma));
    m_gamma->setObjectName(QStringLiteral("gammaSlider"));
    m_ocioDisplay->setObjectName(QStringLiteral("ocioDisplayCombo"));
    m_ocioView->setObjectName(QStringLiteral("ocioViewCombo"));
    std::string ocioError;
    if (const std::shared_ptr<const ColorManagement> ocio = ColorManagement::shared(&ocioError)) {
        m_toneMapper->insertSeparator(m_toneMapper->count());
        m_toneMapper->addItem(tr("OCIO display / view"), kOcioEntry);
        for (const std::string& display : ocio->displays())
            m_ocioDisplay->addItem(QString::fromStdString(display), QString::fromStdString(display));
        m_ocioDisplay->setToolTip(tr("OCIO config: %1").arg(QString::fromStdString(ocio->source())));
    } else {
        m_ocioProblem = QString::fromStdString(ocioError);
        m_ocioDisplay->setToolTip(m_ocioProblem);
    }
    m_debugView->setObjectName(QStringLiteral("debugViewCombo"));
    for (int i = 0; i < kDebugViewCount; ++i) {
        // Descriptive labels from render/'s one name table; the data is the name files store.
        const QString name = QString::fromLatin1(toString(DebugView(i)));
        m_debugView->addItem(QString::fromUtf8(debugViewLabel(DebugView(i))), name);
        m_debugView->setItemData(
            i, tr("“%1” in project files and facet render --view").arg(name), Qt::ToolTipRole);
    }
    m_texelDensity->setObjectName(QStringLiteral("texelDensitySpin"));
    m_texelDensity->setRange(1.0, ViewSettings::kMaxTexelDensity);
    m_texelDensity->setDecimals(0);
    m_texelDensity->setSuffix(tr(" texels/m"));
    m_texelDensity->setKeyboardTracking(false);
    m_texelDensity->setToolTip(
        tr("The Texel density view's target: texels of the material's map (base colour's, "
           "else its largest) per metre of surface (per unit of the mesh's file). Green on "
           "target, blue at a quarter or less, red at four times or more."));
    m_msaa->setObjectName(QStringLiteral("msaaCombo"));
    for (int samples : {1, 2, 4, 8, 16})
        m_msaa->addItem(samples == 1 ? tr("Off") : QStringLiteral("%1×").arg(samples), samples);
    m_glLabel->setObjectName(QStringLiteral("viewGlLabel"));
    m_frameLabel->setObjectName(QStringLiteral("viewFrameLabel"));
    m_iblLabel->setObjectName(QStringLiteral("viewIblLabel"));
    for (QLabel* label : {m_glLabel, m_frameLabel, m_iblLabel}) {
        label->setWordWrap(true);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    }
    auto* resetCamera = new QPushButton(tr("Reset Camera"), this);
    resetCamera->setObjectName(QStringLiteral("resetCameraButton"));
    connect(resetCamera, &QPushButton::clicked, this, &ViewDock::resetCameraRequested);

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    auto* sceneForm = new QFormLayout;
    sceneForm->addRow(tr("Mesh"), m_mesh);
    sceneForm->addRow(tr("Field of view"), m_fov);
    sceneForm->addRow(QString(), resetCamera);
    layout->addLayout(sceneForm);
    auto* displayGroup = new QGroupBox(tr("Display"), content);
    auto* displayForm = new QFormLayout(displayGroup);
    displayForm->addRow(tr("Exposure"), m_exposure);
    displayForm->addRow(tr("Tone mapper"), m_toneMapper);
    displayForm->addRow(tr("Encoding"), m_encoding);
    displayForm->addRow(tr("Gamma"), m_gamma);
    displayForm->addRow(tr("OCIO display"), m_ocioDisplay);
    displayForm->addRow(tr("OCIO view"), m_ocioView);
    displayForm->addRow(tr("Debug view"), m_debugView);
    displayForm->addRow(tr("Density target"), m_texelDensity);
    displayForm->addRow(tr("MSAA"), m_msaa);
    layout->addWidget(displayGroup);
    auto* statsGroup = new QGroupBox(tr("Statistics"), content);
    auto* statsLayout = new QVBoxLayout(statsGroup);
    statsLayout->addWidget(m_glLabel);
    statsLayout->addWidget(m_frameLabel);
    statsLayout->addWidget(m_iblLabel);
    layout->addWidget(statsGroup);
    layout->addStretch();
    setWidget(content);

    connect(m_mesh, &QComboBox::activated, this, [this] {
        const QString choice = m_mesh->currentData().toString();
        if (choice == kImportItem) {
            const QString path = QFileDialog::getOpenFileName(this, tr("Import Mesh"), {},
                tr("Meshes (*.glb *.gltf *.obj *.fbx *.ply *.stl *.dae);;All files (*)"));
            if (path.isEmpty() || !importMesh(path))
                onDocumentChanged(DocumentChange::Mesh); // show the mesh there is
            return;
        }
        editView(tr("Mesh %1").arg(m_mesh->currentText()), MergeId::None,
            [&](ViewSettings& view) { view.mesh = choice.toStdString(); });
    });
    connect(m_fov, &ValueSlider::valueEdited, this, [this](double degrees) {
        Camera camera = m_document->project().camera;
        camera.verticalFovDegrees = degrees;
        m_document->setCamera(camera);
    });
    connect(m_exposure, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
    connect(m_exposure, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
    connect(m_exposure, &ValueSlider::valueEdited, this, [this](double ev) {
        editView(tr("Exposure"), MergeId::Exposure, [&](ViewSettings& view) { view.exposureEV = ev; });
    });
    connect(m_gamma, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
    connect(m_gamma, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
    connect(m_gamma, &ValueSlider::valueEdited, this, [this](double gamma) {
        editView(tr("Gamma"), MergeId::Gamma, [&](ViewSettings& view) { view.gamma = gamma; });
    });
    connect(m_toneMapper, &QComboBox::activated, this, [this] {
        const int choice = m_toneMapper->currentData().toInt();
        editView(tr("Tone Mapper"), MergeId::None, [&](ViewSettings& view) {
            if (choice == kOcioEntry) {
                std::string error;
                const auto ocio = ColorManagement::shared(&error);
                if (!ocio || m_ocioDisplay->count() == 0)
                    return;
                view.ocioDisplay = view.ocioDisplay.empty() ? ocio->defaultDisplay() : view.ocioDisplay;
                view.ocioView = ocio->defaultView(view.ocioDisplay);
                return;
            }
            view.toneMapper = ToneMapper(choice);
            view.ocioDisplay.clear();
            view.ocioView.clear();
        });
    });
    connect(m_encoding, &QComboBox::activated, this, [this] {
        const auto encoding = DisplayEncoding(m_encoding->currentData().toInt());
        editView(tr("Display Encoding"), MergeId::None,
            [&](ViewSettings& view) { view.displayEncoding = encoding; });
    });
    connect(m_ocioDisplay, &QComboBox::activated, this, [this] {
        const std::string display = m_ocioDisplay->currentData().toString().toStdString();
        std::string error;
        const auto ocio = ColorManagement::shared(&error);
        if (!ocio)
            return;
        editView(tr("OCIO Display"), MergeId::None, [&](ViewSettings& view) {
            view.ocioDisplay = display;
            view.ocioView = ocio->defaultView(display);
        });
    });
    connect(m_ocioView, &QComboBox::activated, this, [this] {
        const std::string viewName = m_ocioView->currentData().toString().toStdString();
        editView(tr("OCIO View"), MergeId::None, [&](ViewSettings& view) {
            if (view.ocioDisplay.empty())
                view.ocioDisplay = m_ocioDisplay->currentData().toString().toStdString();
            view.ocioView = viewName;
        });
    });
    connect(m_debugView, &QComboBox::activated, this, [this] {
        const auto chosen = debugViewFromString(m_debugView->currentData().toString().toStdString());
        editView(tr("Debug View"), MergeId::None,
            [&](ViewSettings& view) { view.debugView = chosen.value_or(DebugView::None); });
    });
    connect(m_texelDensity, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (m_document->project().view.texelDensityTarget == value)
            return; // shown from the document
        editView(tr("Texel Density Target"), MergeId::None,
            [&](ViewSettings& view) { view.texelDensityTarget = value; });
    });
    connect(m_msaa, &QComboBox::activated, this, [this] {
        const int samples = m_msaa->currentData().toInt();
        editView(tr("MSAA"), MergeId::None, [&](ViewSettings& view) { view.msaaSamples = samples; });
    });
    connect(m_document, &Document::changed, this, &ViewDock::onDocumentChanged);
    onDocumentChanged(DocumentChange::WholeProject);
}

ViewDock::~ViewDock() = default;

void ViewDock::editView(
    const QString& undoText, int mergeId, const std::function<void(ViewSettings&)>& change)
{
    ViewSettings view = m_document->project().view;
    change(view);
    m_document->setView(view, undoText, mergeId);
}

bool ViewDock::importMesh(const QString& path)
{
    const QFileInfo info(path);
    if (!info.isFile()) {
        Q_EMIT message(tr("Cannot import %1: no such file").arg(path));
        return false;
    }
    // SceneController loads it and reports a file it cannot read (the sphere stays then).
    editView(tr("Import Mesh %1").arg(info.fileName()), MergeId::None,
        [&](ViewSettings& view) { view.mesh = info.absoluteFilePath().toStdString(); });
    return true;
}

void ViewDock::fillOcioViews(const QString& display)
{
    const QSignalBlocker blocker(m_ocioView);
    m_ocioView->clear();
    std::string error;
    const auto ocio = ColorManagement::shared(&error);
    if (!ocio || display.isEmpty())
        return;
    if (const auto views = ocio->views(display.toStdString(), &error))
        for (const std::string& view : *views)
            m_ocioView->addItem(QString::fromStdString(view), QString::fromStdString(view));
}

void ViewDock::onDocumentChanged(DocumentChanges changes)
{
    const Project& project = m_document->project();
    if (changes & DocumentChange::Camera)
        m_fov->setValue(project.camera.verticalFovDegrees);
    if (changes & DocumentChange::Mesh) {
        const QString mesh = QString::fromStdString(project.view.mesh);
        if (m_mesh->findData(mesh) < 0) {
            // A mesh file: an entry of its own above the separator.
            m_mesh->insertItem(int(primitiveNames().size()), QFileInfo(mesh).fileName(), mesh);
            m_mesh->setItemData(int(primitiveNames().size()), mesh, Qt::ToolTipRole);
        }
        selectData(m_mesh, mesh);
    }
    if (!(changes & DocumentChange::View))
        return;
    const ViewSettings& view = project.view;
    m_exposure->setValue(view.exposureEV);
    m_gamma->setValue(view.gamma);
    const bool ocio = !view.ocioDisplay.empty();
    selectData(m_toneMapper, ocio ? kOcioEntry : int(view.toneMapper));
    selectData(m_encoding, int(view.displayEncoding));
    selectData(m_ocioDisplay, QString::fromStdString(view.ocioDisplay));
    fillOcioViews(ocio ? QString::fromStdString(view.ocioDisplay) : m_ocioDisplay->currentData().toString());
    selectData(m_ocioView, QString::fromStdString(view.ocioView));
    selectData(m_debugView, QString::fromLatin1(toString(view.debugView)));
    selectData(m_msaa, view.msaaSamples);
    {
        const QSignalBlocker blocker(m_texelDensity);
        m_texelDensity->setValue(view.texelDensityTarget);
    }
    m_texelDensity->setEnabled(view.debugView == DebugView::TexelDensity);
    m_encoding->setEnabled(!ocio);
    m_gamma->setEnabled(!ocio && view.displayEncoding == DisplayEncoding::Gamma);
    m_ocioDisplay->setEnabled(ocio);
    m_ocioView->setEnabled(ocio);
}

void ViewDock::showGLInfo(const GLInfo& info)
{
    m_glLabel->setText(
        tr("OpenGL %1\n%2").arg(QString::fromStdString(info.version), QString::fromStdString(info.renderer)));
}

void ViewDock::showFrameStats(const ViewportFrameStats& stats)
{
    m_frameLabel->setText(tr("Frame: %1 (%2 draw calls)").arg(stats.summary()).arg(stats.render.drawCalls));
    m_iblLabel->setText(stats.ibl.msTotal > 0.0
            ? tr("IBL precompute: %1 ms (%2 passes, %3 from the disk cache)")
                  .arg(stats.ibl.msTotal, 0, 'f', 0)
                  .arg(stats.ibl.passesRun)
                  .arg(stats.ibl.cacheHitsDisk)
            : tr("IBL precompute: none yet"));
}

} // namespace facet
