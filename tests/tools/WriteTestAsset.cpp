// Writes the tests' glTF assets (support/TestAssets.h) from CTest, for the command-line tests that
// open one (`facet PATH.glb`), and for looking at the window by hand:
//
//   write_test_asset two-materials OUT.glb
//   write_test_asset showcase OUT.glb

#include "TestAssets.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStringList>

#include <cstdio>

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList arguments = QCoreApplication::arguments();
    if (arguments.size() != 3
        || (arguments[1] != QLatin1String("two-materials") && arguments[1] != QLatin1String("showcase"))) {
        std::fprintf(stderr, "usage: write_test_asset two-materials|showcase OUT.glb\n");
        return 2;
    }
    const QString path = arguments[2];
    QDir().mkpath(QFileInfo(path).absolutePath());
    QString error;
    const bool ok = arguments[1] == QLatin1String("showcase")
        ? facet::test::writeShowcaseAsset(path, &error)
        : facet::test::writeTwoMaterialAsset(path, &error);
    if (!ok) {
        std::fprintf(stderr, "write_test_asset: %s\n", qPrintable(error));
        return 1;
    }
    std::printf("write_test_asset: wrote %s\n", qPrintable(path));
    return 0;
}
