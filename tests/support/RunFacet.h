#pragma once
// The facet executable run as a script runs it (no display server), for the tests of
// `facet render` (RenderCommandTest, RenderCommandImageTest). Compiled into those tests only:
// they define FACET_EXECUTABLE (tests/CMakeLists.txt).

#include "TestSupport.h"

#include <QProcessEnvironment>
#include <QStringList>

namespace facet::test {

// Runs FACET_EXECUTABLE with `arguments`, the variables in `extra` added to its environment.
ProcessResult runFacet(const QStringList& arguments, const QProcessEnvironment& extra = QProcessEnvironment());

} // namespace facet::test
