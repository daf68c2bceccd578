#include "ui/widgets/ProblemBar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QToolButton>

#include <algorithm>

namespace facet {

ProblemBar::ProblemBar(QWidget* parent)
    : QWidget(parent)
    , m_icon(new QLabel(this))
    , m_text(new QLabel(this))
    , m_dismiss(new QToolButton(this))
{
    setObjectName(QStringLiteral("problemBar"));
    const int iconSize = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    m_icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning, nullptr, this).pixmap(iconSize));
    m_text->setObjectName(QStringLiteral("problemText"));
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_text->setTextFormat(Qt::PlainText);
    // One line that may be long (a file name and its problem): it gives way to the window's width
    // instead of widening it, and the tooltip has the whole text.
    m_text->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_dismiss->setObjectName(QStringLiteral("dismissProblems"));
    m_dismiss->setText(tr("Dismiss"));
    m_dismiss->setToolTip(tr("Hide these problems (they come back if they happen again)"));
    connect(m_dismiss, &QToolButton::clicked, this, &ProblemBar::dismiss);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    layout->addWidget(m_icon);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_dismiss);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    refresh();
}

void ProblemBar::setProblem(const QString& subject, const QString& text)
{
    const auto same = [&subject](const auto& problem) { return problem.first == subject; };
    const auto found = std::find_if(m_problems.begin(), m_problems.end(), same);
    if (text.isEmpty() && found == m_problems.end())
        return;
    if (found != m_problems.end())
        m_problems.erase(found);
    if (!text.isEmpty())
        m_problems.emplace_back(subject, text);
    refresh();
}

QStringList ProblemBar::problems() const
{
    QStringList texts;
    for (auto it = m_problems.rbegin(); it != m_problems.rend(); ++it)
        texts.append(it->second);
    return texts;
}

void ProblemBar::dismiss()
{
    if (m_problems.empty())
        return;
    m_problems.clear();
    refresh();
}

void ProblemBar::refresh()
{
    const QStringList texts = problems();
    if (texts.isEmpty()) {
        m_text->clear();
        m_text->setToolTip({});
    } else if (texts.size() == 1) {
        m_text->setText(texts.first());
        m_text->setToolTip(texts.first());
    } else {
        m_text->setText(tr("%1 (and %n more)", nullptr, int(texts.size()) - 1).arg(texts.first()));
        m_text->setToolTip(texts.join(QLatin1Char('\n')));
    }
    Q_EMIT problemsChanged(!texts.isEmpty());
}

} // namespace facet
