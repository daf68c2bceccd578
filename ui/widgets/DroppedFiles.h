#pragma once
// The local files and folders a drag carries (a map slot, the Texture Maps dock and the viewport
// take drops). Remote URLs are left out: Facet reads only local files.

#include <QMimeData>
#include <QStringList>
#include <QUrl>

namespace facet {

inline QStringList droppedLocalFiles(const QMimeData* mime)
{
    QStringList files;
    if (!mime || !mime->hasUrls())
        return files;
    for (const QUrl& url : mime->urls())
        if (url.isLocalFile())
            files.append(url.toLocalFile());
    return files;
}

} // namespace facet
