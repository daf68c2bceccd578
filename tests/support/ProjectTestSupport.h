#pragma once
// What the project file's tests share (ProjectTest, ProjectLoadingTest): a project in which every
// field differs from its default, and a file's bytes. Compiled into those tests only.

#include <QByteArray>
#include <QString>

#include "core/project/Project.h"

namespace facet::test {

// The bytes of the file at `path`; empty when it cannot be read.
QByteArray readAll(const QString& path);

// A project in which every field differs from its default; texture, environment and mesh paths
// under `root`.
Project everythingChanged(const QString& root);

} // namespace facet::test
