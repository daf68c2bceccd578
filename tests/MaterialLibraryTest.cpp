// The project's material library (core/material/MaterialLibrary.h): finding a material by name or index,
// for `facet sheet PROJECT.json#NAME`, with names that need not be unique; naming new materials.

#include <QtTest/QTest>

#include "core/material/MaterialLibrary.h"
#include "core/project/Project.h"

using namespace facet;

namespace {
// Materials named as a glTF import may name them: "Material 1" stands for an unnamed material 1,
// and an asset may repeat a name.
Project library(std::initializer_list<const char*> names)
{
    Project p;
    p.materials.clear();
    for (const char* name : names)
        p.materials.emplace_back().name = name;
    return p;
}
} // namespace

class MaterialLibraryTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void findMaterial_data()
    {
        QTest::addColumn<QString>("selector");
        QTest::addColumn<int>("expected"); // -1: refused
        QTest::addColumn<QString>("message");
        QTest::newRow("a unique name") << "Visor" << 1 << "";
        QTest::newRow("names are exact: case")
            << "visor" << -1
            << "findMaterial: no material is named \"visor\" (the materials: \"Shell\", \"Visor\", \"Trim\", "
               "\"Trim\", \"Material 1\", \"2\")";
        QTest::newRow("names are exact: spaces") << "Visor " << -1 << "no material is named \"Visor \"";
        QTest::newRow("a generated name is a name") << "Material 1" << 4 << "";
        QTest::newRow("a shared name is refused")
            << "Trim" << -1
            << "findMaterial: 2 materials are named \"Trim\" (indices 2, 3): name one by its index";
        QTest::newRow("an index") << "3" << 3 << "";
        QTest::newRow("index 0") << "0" << 0 << "";
        QTest::newRow("leading zeros are still an index") << "003" << 3 << "";
        QTest::newRow("digits are an index, even where a name matches") << "2" << 2 << "";
        QTest::newRow("index past the end")
            << "6" << -1 << "findMaterial: index 6 is not a material (there are 6, from 0)";
        QTest::newRow("an index too large to read")
            << "99999999999999999999999" << -1 << "is not a material (there are 6, from 0)";
        QTest::newRow("a negative number is a name") << "-1" << -1 << "no material is named \"-1\"";
        QTest::newRow("empty") << "" << -1
                               << "findMaterial: empty selector (expected a material's name or index)";
    }
    void findMaterial()
    {
        QFETCH(QString, selector);
        QFETCH(int, expected);
        QFETCH(QString, message);
        const Project p = library({"Shell", "Visor", "Trim", "Trim", "Material 1", "2"});
        std::string error;
        const std::optional<int> found = facet::findMaterial(p, selector.toStdString(), &error);
        if (expected >= 0) {
            QVERIFY2(found, error.c_str());
            QCOMPARE(*found, expected);
        } else {
            QVERIFY(!found);
            QVERIFY2(error.find(message.toStdString()) != std::string::npos, error.c_str());
        }
    }

    // A large library lists a few names, not all of them.
    void longListsAreCut()
    {
        Project p;
        p.materials.resize(100);
        std::string error;
        QVERIFY(!facet::findMaterial(p, "Steel", &error));
        QVERIFY2(error.find("and 92 more)") != std::string::npos, error.c_str());
        QVERIFY(error.size() < 300);
    }

    void unusedMaterialName_data()
    {
        QTest::addColumn<QString>("base");
        QTest::addColumn<QString>("expected");
        QTest::newRow("free") << "Snapshot"
                              << "Snapshot";
        QTest::newRow("taken") << "Trim"
                               << "Trim 2";
        QTest::newRow("taken twice") << "Shell"
                                     << "Shell 3";
    }
    void unusedMaterialName()
    {
        QFETCH(QString, base);
        QFETCH(QString, expected);
        const Project p = library({"Shell", "Trim", "Shell 2"});
        QCOMPARE(QString::fromStdString(facet::unusedMaterialName(p, base.toStdString())), expected);
    }
};

QTEST_GUILESS_MAIN(MaterialLibraryTest)
#include "MaterialLibraryTest.moc"
