#include "ui/dialogs/SaveImageDialog.h"

#include "core/image/VideoEncoder.h"
#include "ui/viewport/ViewportRenderer.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace facet {

namespace {

// The size a still had last, kept while the view has the size it had then (a new window size
// starts from the view's again).
constexpr const char* kSizeKey = "saveImage/size";
constexpr const char* kSizeOfViewKey = "saveImage/sizeOfView";
constexpr const char* kTransparentKey = "saveImage/transparent";
constexpr const char* kFramesKey = "turntable/frames";
constexpr const char* kSubjectKey = "turntable/subject";
constexpr const char* kFormatKey = "turntable/format";
constexpr const char* kFpsKey = "turntable/fps";

QSpinBox* pixelSpin(QWidget* parent, const char* name, int value)
{
    auto* spin = new QSpinBox(parent);
    spin->setObjectName(QLatin1String(name));
    spin->setRange(1, kMaxStillSide);
    spin->setSuffix(QObject::tr(" px"));
    spin->setValue(value);
    return spin;
}

} // namespace

SaveImageDialog::SaveImageDialog(Kind kind, QSize viewSize, QWidget* parent)
    : QDialog(parent)
    , m_kind(kind)
    , m_viewSize(viewSize)
{
    const QSettings settings;
    setWindowTitle(kind == Kind::Still ? tr("Save Image") : tr("Save Turntable"));
    QSize size = viewSize;
    if (settings.value(QLatin1String(kSizeOfViewKey)).toSize() == viewSize) {
        const QSize remembered = settings.value(QLatin1String(kSizeKey)).toSize();
        if (remembered.isValid())
            size = remembered;
    }
    m_width = pixelSpin(this, "saveImageWidth", size.width());
    m_height = pixelSpin(this, "saveImageHeight", size.height());
    auto* viewSizeButton = new QPushButton(tr("View Size"), this);
    viewSizeButton->setObjectName(QStringLiteral("saveImageViewSize"));
    viewSizeButton->setToolTip(
        tr("The view's own size: %1 x %2").arg(viewSize.width()).arg(viewSize.height()));
    connect(viewSizeButton, &QPushButton::clicked, this, [this] {
        m_width->setValue(m_viewSize.width());
        m_height->setValue(m_viewSize.height());
    });
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QStringLiteral("×"), this));
    sizeRow->addWidget(m_height);
    sizeRow->addWidget(viewSizeButton);
    m_transparent = new QCheckBox(tr("Transparent background"), this);
    m_transparent->setObjectName(QStringLiteral("saveImageTransparent"));
    m_transparent->setToolTip(tr("Pixels that miss the object get alpha 0 (PNG: straight alpha; EXR: "
                                 "premultiplied). A video has no alpha."));
    m_transparent->setChecked(settings.value(QLatin1String(kTransparentKey), false).toBool());

    auto* form = new QFormLayout;
    form->addRow(tr("Size:"), sizeRow);
    form->addRow(QString(), m_transparent);
    if (kind == Kind::Turntable) {
        m_frames = new QSpinBox(this);
        m_frames->setObjectName(QStringLiteral("turntableFrames"));
        m_frames->setRange(2, kMaxFrames);
        m_frames->setValue(settings.value(QLatin1String(kFramesKey), 36).toInt());
        m_frames->setToolTip(
            tr("Frames of one full turn: frame i is at 360 i / N degrees, so the sequence loops."));
        m_subject = new QComboBox(this);
        m_subject->setObjectName(QStringLiteral("turntableSubject"));
        m_subject->addItem(tr("Object (lighting and camera fixed)"), int(TurntableSubject::Object));
        m_subject->addItem(tr("Environment (object and camera fixed)"), int(TurntableSubject::Environment));
        m_subject->setCurrentIndex(
            std::max(0, m_subject->findData(settings.value(QLatin1String(kSubjectKey), 0).toInt())));
        m_format = new QComboBox(this);
        m_format->setObjectName(QStringLiteral("turntableFormat"));
        m_format->addItem(tr("PNG frames (as shown)"), int(Format::Png));
        m_format->addItem(tr("OpenEXR frames (linear radiance)"), int(Format::Exr));
        m_format->addItem(tr("MP4 video (H.264, ffmpeg)"), int(Format::Mp4));
        m_format->addItem(tr("WebM video (VP9, ffmpeg)"), int(Format::WebM));
        m_format->setCurrentIndex(
            std::max(0, m_format->findData(settings.value(QLatin1String(kFormatKey), 0).toInt())));
        m_fps = new QSpinBox(this);
        m_fps->setObjectName(QStringLiteral("turntableFps"));
        m_fps->setRange(1, 120);
        m_fps->setSuffix(tr(" frames/s"));
        m_fps->setValue(settings.value(QLatin1String(kFpsKey), 30).toInt());
        m_formatNote = new QLabel(this);
        m_formatNote->setObjectName(QStringLiteral("turntableFormatNote"));
        m_formatNote->setWordWrap(true);
        form->addRow(tr("Frames:"), m_frames);
        form->addRow(tr("Turning:"), m_subject);
        form->addRow(tr("Format:"), m_format);
        form->addRow(tr("Frame rate:"), m_fps);
        form->addRow(QString(), m_formatNote);
        connect(m_format, &QComboBox::currentIndexChanged, this, &SaveImageDialog::updateFormatNote);
        updateFormatNote();
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

void SaveImageDialog::updateFormatNote()
{
    const Format format = Format(m_format->currentData().toInt());
    const bool video = format == Format::Mp4 || format == Format::WebM;
    m_fps->setEnabled(video);
    if (video && findFfmpeg().empty())
        m_formatNote->setText(tr("A video needs ffmpeg, which is not installed (Debian: sudo apt install "
                                 "ffmpeg). PNG frames can be made into a video later."));
    else if (video)
        m_formatNote->setText(tr("One video file; the frames are not kept."));
    else
        m_formatNote->setText(tr("Numbered files: NAME_0000, NAME_0001, …"));
}

SaveImageDialog::Choice SaveImageDialog::choice() const
{
    Choice choice;
    choice.size = QSize(m_width->value(), m_height->value());
    choice.transparent = m_transparent->isChecked();
    if (m_kind == Kind::Turntable) {
        choice.frames = m_frames->value();
        choice.subject = TurntableSubject(m_subject->currentData().toInt());
        choice.format = Format(m_format->currentData().toInt());
        choice.fps = m_fps->value();
    }
    return choice;
}

QString SaveImageDialog::filterFor(Format format)
{
    switch (format) {
    case Format::Png:
        return tr("PNG frames, as shown (*.png)");
    case Format::Exr:
        return tr("OpenEXR frames, linear scene radiance (*.exr)");
    case Format::Mp4:
        return tr("MP4 video (*.mp4)");
    case Format::WebM:
        return tr("WebM video (*.webm)");
    }
    return {};
}

QString SaveImageDialog::suffixFor(Format format)
{
    switch (format) {
    case Format::Png:
        return QStringLiteral("png");
    case Format::Exr:
        return QStringLiteral("exr");
    case Format::Mp4:
        return QStringLiteral("mp4");
    case Format::WebM:
        return QStringLiteral("webm");
    }
    return {};
}

void SaveImageDialog::accept()
{
    QSettings settings;
    const Choice chosen = choice();
    settings.setValue(QLatin1String(kSizeKey), chosen.size);
    settings.setValue(QLatin1String(kSizeOfViewKey), m_viewSize);
    settings.setValue(QLatin1String(kTransparentKey), chosen.transparent);
    if (m_kind == Kind::Turntable) {
        settings.setValue(QLatin1String(kFramesKey), chosen.frames);
        settings.setValue(QLatin1String(kSubjectKey), int(chosen.subject));
        settings.setValue(QLatin1String(kFormatKey), int(chosen.format));
        settings.setValue(QLatin1String(kFpsKey), chosen.fps);
    }
    QDialog::accept();
}

} // namespace facet
