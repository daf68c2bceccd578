#pragma once
// File > Export…: the window's face of `facet export`: a glTF 2.0 asset (.gltf or .glb: the
// materials on the view's mesh, core/gltf/GltfExport) or a texture set (core/export/TextureSetExport: the
// built-in templates, or a template file); the current material or all of them, a size and bit
// depth, and a folder; a live list of the files it will write (and for a texture set where each
// channel comes from: the dry run), updated as the choices change. Export asks before replacing files already
// in the folder, writes the whole set or nothing (a failed write removes what it made) and says
// what it wrote, or what failed with the file named. The choices are remembered (QSettings).

#include <functional>
#include <optional>

#include <QDialog>
#include <QString>
#include <QStringList>

#include "core/export/ExportTemplate.h"
#include "core/export/TextureSetExport.h"
#include "core/project/Project.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace facet {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    // `baseName`: the glTF asset's file name without extension (the project's name,
    // Document::exportBaseName). `projectFolder`: the project's (or its asset's) folder, where a
    // project's first export goes; the folder chosen last for that project after that, and for a
    // project without a folder the last one chosen at all (else the home folder).
    ExportDialog(const Project& project, const QString& baseName = QStringLiteral("material"),
        QWidget* parent = nullptr, const QString& projectFolder = QString());

    // Asked with the files an export would replace; true replaces them. Default: a message box.
    void setConfirmReplace(std::function<bool(const QStringList& existing)> confirm);
    // Adds a template file to the template list and selects it (Browse… does this after its file
    // dialog). False, with the problem shown, when it cannot be read.
    bool useTemplateFile(const QString& path);
    void setFolder(const QString& folder);

    // The dry run's text for the current choices, or the problem that stops the export.
    QString preview() const;
    // Exports with the current choices. False with message() saying why.
    bool exportNow();
    // What the last export did: "Exported 7 files to /out (Unreal Engine)" or the error.
    QString message() const { return m_message; }

Q_SIGNALS:
    void exported(const QString& message);

private:
    void updatePreview();
    std::optional<ExportTemplate> chosenTemplate(std::string* error) const;
    std::vector<Material> chosenMaterials() const;
    TextureSetOptions chosenOptions() const;
    void browseTemplate();
    void browseFolder();
    void remember() const;

    Project m_project;
    QComboBox* m_template = nullptr;
    QComboBox* m_materials = nullptr;
    QComboBox* m_size = nullptr;
    QComboBox* m_bitDepth = nullptr;
    QLineEdit* m_folder = nullptr;
    QPlainTextEdit* m_preview = nullptr;
    QLabel* m_status = nullptr;
    QPushButton* m_export = nullptr;
    QStringList m_templateFiles; // user templates added, after the built-ins
    bool isGltf() const;
    QString gltfPath() const;

    QString m_baseName;
    QString m_projectFolder; // the project's folder (empty: none), for the per-project remembered folder
    std::optional<TextureSetExport> m_job; // the plan the preview shows (texture sets)
    std::vector<std::string> m_gltfFiles; // the files a glTF export writes
    QString m_problem;
    QString m_message;
    std::function<bool(const QStringList&)> m_confirmReplace;
};

} // namespace facet
