#include "RunFacet.h"

namespace facet::test {

ProcessResult runFacet(const QStringList& arguments, const QProcessEnvironment& extra)
{
    return runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments, extra);
}

} // namespace facet::test
