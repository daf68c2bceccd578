#pragma once
// Problems that stay in view until the artist dismisses them or their cause goes away: a texture,
// environment or mesh that did not load, a save or an autosave that failed. The status bar is for
// news and the next note overwrites it ("Lighting of studio ready" came a moment after "wood.png
// is a folder, not a file" and hid it); a problem here is not overwritten.
//
// Each problem has a subject (what it is about: "environment", "mesh", "map:<path>", "file",
// "autosave"): a new problem of the same subject replaces the old one, and an empty text clears
// it (the environment loaded after all). The bar shows the newest problem, "and N more" with the
// rest in its tooltip, and a Dismiss button that clears them all. MainWindow puts it in a
// toolbar row above the view that is hidden while there is no problem.

#include <QString>
#include <QStringList>
#include <QWidget>

#include <utility>
#include <vector>

class QLabel;
class QToolButton;

namespace facet {

class ProblemBar : public QWidget {
    Q_OBJECT
public:
    explicit ProblemBar(QWidget* parent = nullptr);

    // A problem about `subject` in the window's wording (ui/widgets/WindowMessages.h); "" clears it.
    void setProblem(const QString& subject, const QString& text);
    // The problems shown, newest first.
    QStringList problems() const;
    bool hasProblems() const { return !m_problems.empty(); }

public Q_SLOTS:
    void dismiss();

Q_SIGNALS:
    // hasProblems() may have changed (the toolbar row shows and hides with it).
    void problemsChanged(bool hasProblems);

private:
    void refresh();

    QLabel* m_icon = nullptr;
    QLabel* m_text = nullptr;
    QToolButton* m_dismiss = nullptr;
    std::vector<std::pair<QString, QString>> m_problems; // (subject, text), oldest first
};

} // namespace facet
