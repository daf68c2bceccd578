#pragma once
// The choices before File > Save Image… and File > Save Turntable… (docs/app.md, "Saving images"),
// as Marmoset Toolbag's render settings give them: the size in pixels (the view's own by default;
// up to kMaxStillSide a side, rendered offscreen), a transparent background; for a turntable the
// frames of a full turn, what turns (the object or the environment), the format (numbered PNG or
// EXR frames, or an MP4 or WebM video by ffmpeg) and the video's frame rate. The choices are
// remembered (QSettings) for the next time; the size only while the view keeps its size.

#include "render/Turntable.h"

#include <QDialog>
#include <QSize>

class QCheckBox;
class QComboBox;
class QLabel;
class QSpinBox;

namespace facet {

class SaveImageDialog : public QDialog {
    Q_OBJECT
public:
    enum class Kind { Still, Turntable };
    enum class Format { Png, Exr, Mp4, WebM };
    struct Choice {
        QSize size;
        bool transparent = false;
        int frames = 36;
        TurntableSubject subject = TurntableSubject::Object;
        Format format = Format::Png;
        int fps = 30;
    };
    static constexpr int kMaxFrames = 3600;

    SaveImageDialog(Kind kind, QSize viewSize, QWidget* parent = nullptr);

    Choice choice() const;
    // The file dialog's filter and default suffix for a turntable's format.
    static QString filterFor(Format format);
    static QString suffixFor(Format format);

    QSpinBox* widthSpin() const { return m_width; }
    QSpinBox* heightSpin() const { return m_height; }
    QCheckBox* transparentCheck() const { return m_transparent; }
    QSpinBox* framesSpin() const { return m_frames; }
    QComboBox* subjectCombo() const { return m_subject; }
    QComboBox* formatCombo() const { return m_format; }
    QSpinBox* fpsSpin() const { return m_fps; }

    // Remembers the choices (OK).
    void accept() override;

private:
    void updateFormatNote();

    Kind m_kind;
    QSize m_viewSize;
    QSpinBox* m_width;
    QSpinBox* m_height;
    QCheckBox* m_transparent;
    QSpinBox* m_frames = nullptr;
    QComboBox* m_subject = nullptr;
    QComboBox* m_format = nullptr;
    QSpinBox* m_fps = nullptr;
    QLabel* m_formatNote = nullptr;
};

} // namespace facet
