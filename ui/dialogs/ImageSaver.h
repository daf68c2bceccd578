#pragma once
// File > Save Image… (F12) and File > Save Turntable… (Shift+F12) of the main window
// (docs/app.md, "Saving images"): the single view rendered again offscreen at a chosen size, with
// a transparent background if asked, converged to the project's IBL samples, as a PNG (what it
// shows) or a linear EXR; a turntable of it (render/Turntable.h) as numbered frames or a video by
// ffmpeg (core/image/VideoEncoder.h), with a progress dialog that can stop it; in a Compare mode the
// grid as shown (PNG). Not a widget: the window's menus call it and its messages go to the status
// bar.

#include "ui/dialogs/SaveImageDialog.h"

#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace facet {

class CompareView;
class Document;
class ViewportWidget;

class ImageSaver : public QObject {
    Q_OBJECT
public:
    // `window`: the dialogs' parent; `gridShown` says whether the Compare view is shown.
    ImageSaver(QWidget* window, Document* document, ViewportWidget* viewport, CompareView* compareView,
        std::function<bool()> gridShown);

    // The menu actions: the choices (SaveImageDialog), a file, then the work below; failures in a
    // message box.
    void saveImage();
    void saveTurntable();

    // Without dialogs (tests, scripts): false with *error (also sent as statusMessage).
    // `choice.size` empty: the view's own size. The grid ignores the choices (it saves as shown).
    bool saveImageTo(const QString& path, const SaveImageDialog::Choice& choice, QString* error);
    // `path` ends as the choice's format says (.png, .exr: numbered frames, turntableFramePath;
    // .mp4, .webm: a video). `cancelled` (optional) is asked between frames.
    bool saveTurntableTo(const QString& path, const SaveImageDialog::Choice& choice, QString* error,
        const std::function<bool()>& cancelled = {});

Q_SIGNALS:
    void statusMessage(const QString& text);

private:
    bool fail(const QString& why, QString* error);
    QString chooseFile(const QString& title, const QString& filters, const QString& suffix);

    QWidget* m_window;
    Document* m_document;
    ViewportWidget* m_viewport;
    CompareView* m_compareView;
    std::function<bool()> m_gridShown;
};

} // namespace facet
