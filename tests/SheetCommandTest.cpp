// `facet sheet` (app/SheetCommand.h), run as users run it: the facet executable with no display.
// The sheets are read back and their content checked, not only their existence: a roughness
// wedge's highlight falls and widens along the axis; each axis reaches its cells; two
// environments give different cells; a cell equals `facet render` of the same material and
// environment; the EXR header holds the layout; labels are drawn in margins of a PNG; bad values
// name their flag, and a missing environment or material is named and nothing is written.

#include "core/image/Image.h"
#include "core/image/ImageMetrics.h"
#include "core/project/Light.h"
#include "core/project/Project.h"

#include "TestSupport.h"

#include <OpenImageIO/imageio.h>

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace facet;
using facet::test::strings;
using Result = facet::test::ProcessResult;

namespace {

Result runFacet(const QStringList& arguments)
{
    return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments);
}

QString describe(const Result& r)
{
    return QStringLiteral("exit %1\nstdout: %2\nstderr: %3").arg(r.exitCode).arg(r.out, r.err);
}

// Cell (row, column) of a sheet without margins (EXR, or PNG with --labels off).
Image cellOf(const Image& sheet, int row, int column, int width, int height)
{
    Image cell(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            cell.at(x, y) = sheet.at(column * width + x, row * height + y);
    return cell;
}

double luminance(const glm::vec4& c)
{
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

double meanLuminance(const Image& image)
{
    double sum = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            sum += luminance(image.at(x, y));
    return sum / double(image.pixelCount());
}

// The EXR header's string attribute `name` (empty when absent).
std::string exrAttribute(const QString& path, const char* name)
{
    auto input = OIIO::ImageInput::open(path.toStdString());
    if (!input)
        return {};
    return input->spec().get_string_attribute(name);
}

} // namespace

class SheetCommandTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

    std::optional<Image> load(const QString& file)
    {
        std::string error;
        auto image = Image::load(file.toStdString(), &error);
        if (!image)
            qWarning("%s", error.c_str());
        return image;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(facet::test::writeConstantExr(path(QStringLiteral("bright.exr")), 2.0f));
        // A sphere lit by one directional light in a black world: a dielectric with a black base
        // colour shows its specular highlight alone.
        Project lit = Project::defaultProject();
        lit.environment.source = "uniform:0";
        lit.material().setBaseColor(glm::dvec3(0.0), 1.0);
        lit.material().setFactor(MapSlot::Metallic, 0.0);
        Light light;
        light.type = LightType::Directional;
        light.direction = glm::normalize(glm::dvec3(-0.3, -0.3, -1.0));
        light.intensity = 3.0;
        lit.lights.push_back(light);
        std::string error;
        QVERIFY2(lit.save(path(QStringLiteral("lit.json")).toStdString(), &error), error.c_str());
    }

    void roughnessWedgeHighlightFallsAndWidens()
    {
        const QString out = path(QStringLiteral("wedge.exr"));
        const Result r = runFacet({QStringLiteral("sheet"), path(QStringLiteral("lit.json")), QStringLiteral("--wedge"),
            QStringLiteral("roughness=0.2,0.35,0.5,0.65,0.8"), QStringLiteral("--cell"), QStringLiteral("96x96"),
            QStringLiteral("-o"), out});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const auto sheet = load(out);
        QVERIFY(sheet);
        QCOMPARE(sheet->width(), 96);
        QCOMPARE(sheet->height(), 5 * 96);
        double previousPeak = 1e30;
        int previousWidth = 0;
        for (int row = 0; row < 5; ++row) {
            const Image cell = cellOf(*sheet, row, 0, 96, 96);
            double peak = 0.0;
            for (int y = 0; y < 96; ++y)
                for (int x = 0; x < 96; ++x)
                    peak = std::max(peak, luminance(cell.at(x, y)));
            int width = 0; // pixels at more than half the peak: the highlight's area
            for (int y = 0; y < 96; ++y)
                for (int x = 0; x < 96; ++x)
                    width += luminance(cell.at(x, y)) > 0.5 * peak ? 1 : 0;
            QVERIFY2(peak < previousPeak,
                qPrintable(QStringLiteral("row %1: peak %2 after %3").arg(row).arg(peak).arg(previousPeak)));
            QVERIFY2(width > previousWidth,
                qPrintable(QStringLiteral("row %1: %2 pixels after %3").arg(row).arg(width).arg(previousWidth)));
            previousPeak = peak;
            previousWidth = width;
        }
        QCOMPARE(exrAttribute(out, "facet:rows"), std::string("5"));
        QCOMPARE(exrAttribute(out, "facet:columns"), std::string("1"));
        QCOMPARE(exrAttribute(out, "facet:cellWidth"), std::string("96"));
        QCOMPARE(exrAttribute(out, "facet:rowLabels"),
            std::string("roughness 0.2\nroughness 0.35\nroughness 0.5\nroughness 0.65\nroughness 0.8"));
    }

    // The material flags (the property registry's, as `facet render` has them) set every row's
    // material: a dark base colour darkens both preset rows, a roughness of 1 spreads gold's highlight.
    void materialFlagsSetEveryRow()
    {
        const auto render = [&](const QString& name, const QStringList& flags) -> std::optional<Image> {
            const QString out = path(name);
            const Result r = runFacet(
                QStringList {QStringLiteral("sheet"), QStringLiteral("--materials"),
                    QStringLiteral("gold,copper"), QStringLiteral("--cell"), QStringLiteral("48x48"),
                    QStringLiteral("--background"), QStringLiteral("color:0,0,0"), QStringLiteral("-o"), out}
                + flags);
            if (r.exitCode != 0) {
                qWarning("%s", qPrintable(describe(r)));
                return std::nullopt;
            }
            return load(out);
        };
        const auto plain = render(QStringLiteral("plain.exr"), {});
        const auto dark = render(QStringLiteral("dark.exr"), strings({"--base-color", "0.1,0.1,0.1"}));
        QVERIFY(plain && dark);
        for (int row = 0; row < 2; ++row) {
            const double ratio = meanLuminance(cellOf(*dark, row, 0, 48, 48))
                / meanLuminance(cellOf(*plain, row, 0, 48, 48));
            QVERIFY2(ratio < 0.5, qPrintable(QStringLiteral("row %1: %2").arg(row).arg(ratio)));
        }
    }

    void axesReachTheirCells_data()
    {
        // Two cells along the columns (--wedge2 or --envs): the second's mean luminance over the
        // first's must lie in [low, high].
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<double>("low");
        QTest::addColumn<double>("high");
        QTest::newRow("envs: uniform 0.25 vs a 2.0 file") << strings({"--envs", "uniform:0.25,{dir}/bright.exr"}) << 4.0
                                                         << 12.0;
        QTest::newRow("wedge2 exposure -1 vs +1 (linear EXR: no effect)")
            << strings({"--wedge", "roughness=0.5", "--wedge2", "exposure=-1,1"}) << 0.999 << 1.001;
        QTest::newRow("wedge2 env") << strings({"--wedge", "roughness=0.5", "--wedge2", "env=uniform:1,uniform:0.5"})
                                    << 0.45 << 0.55;
        // Gold's base colour as a dielectric (diffuse + 4% specular) against the metal (measured 1.20
        // in the built-in studio): not applying the axis gives exactly 1.
        QTest::newRow("wedge2 metallic 0 vs 1 (gold's base colour)")
            << strings({"--materials", "gold", "--wedge", "roughness=0.4", "--wedge2", "metallic=0,1"}) << 1.1 << 2.0;
    }

    void axesReachTheirCells()
    {
        QFETCH(QStringList, arguments);
        QFETCH(double, low);
        QFETCH(double, high);
        for (QString& argument : arguments)
            argument.replace(QLatin1String("{dir}"), m_dir.path());
        const QString out = path(QStringLiteral("axis.exr"));
        const Result r = runFacet(QStringList {QStringLiteral("sheet"), QStringLiteral("--cell"), QStringLiteral("48x48"),
                                      QStringLiteral("-o"), out}
            + arguments);
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const auto sheet = load(out);
        QVERIFY(sheet);
        QCOMPARE(sheet->width(), 2 * 48);
        const double ratio = meanLuminance(cellOf(*sheet, 0, 1, 48, 48)) / meanLuminance(cellOf(*sheet, 0, 0, 48, 48));
        QVERIFY2(ratio >= low && ratio <= high, qPrintable(QString::number(ratio)));
    }

    void cellEqualsFacetRender_data()
    {
        QTest::addColumn<QString>("format");
        QTest::newRow("exr (linear)") << QStringLiteral("exr");
        QTest::newRow("png (view transform)") << QStringLiteral("png");
    }

    void cellEqualsFacetRender()
    {
        QFETCH(QString, format);
        const QString sheetPath = path(QStringLiteral("pair.") + format);
        Result r = runFacet({QStringLiteral("sheet"), QStringLiteral("--materials"), QStringLiteral("gold,copper"),
            QStringLiteral("--envs"), QStringLiteral("uniform:0.5,") + path(QStringLiteral("bright.exr")),
            QStringLiteral("--cell"), QStringLiteral("64x48"), QStringLiteral("--labels"), QStringLiteral("off"),
            QStringLiteral("-o"), sheetPath});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const QString renderPath = path(QStringLiteral("single.") + format);
        r = runFacet({QStringLiteral("render"), QStringLiteral("--material"), QStringLiteral("copper"),
            QStringLiteral("--env"), path(QStringLiteral("bright.exr")), QStringLiteral("--size"), QStringLiteral("64x48"),
            QStringLiteral("-o"), renderPath});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const auto sheet = load(sheetPath);
        const auto single = load(renderPath);
        QVERIFY(sheet && single);
        QCOMPARE(sheet->width(), 2 * 64);
        QCOMPARE(sheet->height(), 2 * 48);
        // Row 1 (copper), column 1 (bright.exr): the same path, the same pixels. Bound: equal
        // within one 8-bit step (PNG) or exactly (EXR).
        const Image cell = cellOf(*sheet, 1, 1, 64, 48);
        float worst = 0.0f;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(cell.at(x, y)[c] - single->at(x, y)[c]));
        QVERIFY2(worst <= (format == QStringLiteral("png") ? 1.0f / 255.0f + 1e-6f : 0.0f), qPrintable(QString::number(worst)));
        // ... and the other cells are other pictures.
        QVERIFY(meanLuminance(cellOf(*sheet, 1, 0, 64, 48)) < meanLuminance(cell));
    }

    void pngLabelsInMargins()
    {
        const QString labelled = path(QStringLiteral("labelled.png"));
        Result r = runFacet({QStringLiteral("sheet"), QStringLiteral("--wedge"), QStringLiteral("roughness=0,1"),
            QStringLiteral("--envs"), QStringLiteral("uniform:1,uniform:0.5,uniform:0.25"), QStringLiteral("--cell"),
            QStringLiteral("64x64"), QStringLiteral("-o"), labelled});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const auto sheet = load(labelled);
        QVERIFY(sheet);
        const int left = sheet->width() - 3 * 64;
        const int top = sheet->height() - 2 * 64;
        QVERIFY2(left > 16 && top > 8, qPrintable(QStringLiteral("margins %1 x %2").arg(left).arg(top)));
        // Text in the top margin over each column, and left of each row: pixels brighter than the
        // margin's grey.
        const auto brightPixels = [&](int x0, int y0, int x1, int y1) {
            int count = 0;
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x)
                    count += sheet->at(x, y).g > 0.5f ? 1 : 0;
            return count;
        };
        for (int c = 0; c < 3; ++c)
            QVERIFY2(brightPixels(left + c * 64, 0, left + (c + 1) * 64, top) > 10, qPrintable(QString::number(c)));
        for (int row = 0; row < 2; ++row)
            QVERIFY(brightPixels(0, top + row * 64, left, top + (row + 1) * 64) > 10);

        const QString plain = path(QStringLiteral("plain.png"));
        r = runFacet({QStringLiteral("sheet"), QStringLiteral("--wedge"), QStringLiteral("roughness=0,1"),
            QStringLiteral("--envs"), QStringLiteral("uniform:1,uniform:0.5,uniform:0.25"), QStringLiteral("--cell"),
            QStringLiteral("64x64"), QStringLiteral("--labels"), QStringLiteral("off"), QStringLiteral("-o"), plain});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const auto unlabelled = load(plain);
        QVERIFY(unlabelled);
        QCOMPARE(unlabelled->width(), 3 * 64);
        QCOMPARE(unlabelled->height(), 2 * 64);
    }

    void stats()
    {
        // Three environments over two rows: each environment precomputed once, the other row's
        // cells are memory hits.
        const Result r = runFacet({QStringLiteral("sheet"), QStringLiteral("--materials"), QStringLiteral("gold,copper"),
            QStringLiteral("--envs"), QStringLiteral("uniform:1,uniform:0.5,") + path(QStringLiteral("bright.exr")),
            QStringLiteral("--cell"), QStringLiteral("32x32"), QStringLiteral("--stats"), QStringLiteral("-o"),
            path(QStringLiteral("stats.exr"))});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        QVERIFY2(r.out.contains(QStringLiteral("cells: 6 (2 x 3)")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("environments_loaded: 3\n")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("ibl_environments_prepared: 3\n")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("ibl_cache_hits_memory: 3\n")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("total_ms: ")), qPrintable(r.out));
    }

    void texturesOfOneRowAtATime()
    {
        // Rows Red, Blue, Red of two textured materials over three environments: a row's cells
        // share its maps (uploaded once a row, never once a cell), and a row's maps go when the
        // row is done, so the third row uploads Red's map again (one row's maps resident).
        for (const auto& [name, colour] :
            {std::pair {"red.png", Qt::red}, std::pair {"blue.png", Qt::blue}}) {
            QImage image(16, 16, QImage::Format_RGB32);
            image.fill(colour);
            QVERIFY(image.save(path(QString::fromLatin1(name))));
        }
        Project project = Project::defaultProject();
        project.materials[0].name = "Red";
        project.materials[0].map(MapSlot::BaseColor).path = path(QStringLiteral("red.png")).toStdString();
        Material blue = project.materials[0];
        blue.name = "Blue";
        blue.map(MapSlot::BaseColor).path = path(QStringLiteral("blue.png")).toStdString();
        project.materials.push_back(blue);
        const QString file = path(QStringLiteral("textured.json"));
        std::string error;
        QVERIFY2(project.save(file.toStdString(), &error), error.c_str());
        const Result r = runFacet({QStringLiteral("sheet"), QStringLiteral("--materials"),
            file + QStringLiteral("#Red,") + file + QStringLiteral("#Blue,") + file + QStringLiteral("#Red"),
            QStringLiteral("--envs"), QStringLiteral("uniform:1,uniform:0.5,uniform:0.25"),
            QStringLiteral("--cell"), QStringLiteral("32x32"), QStringLiteral("--stats"),
            QStringLiteral("-o"), path(QStringLiteral("textured.exr"))});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        QVERIFY2(r.out.contains(QStringLiteral("cells: 9 (3 x 3)")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("textures_uploaded: 3\n")), qPrintable(r.out));
    }

    // A wedge axis that sweeps nothing in any cell is said before rendering (the sheet is still
    // made); one that another axis makes matter is not. A row per reason and per rescue.
    void axesThatSweepNothingAreNamed_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("warning"); // in stderr; empty: no warning at all
        QTest::newRow("coat roughness without a coat")
            << strings({"--wedge", "clearcoatRoughness=0,1"})
            << QStringLiteral(
                   "--wedge clearcoatRoughness sweeps nothing: clearcoatRoughness shapes the clear coat");
        QTest::newRow("coat roughness, the columns add a coat")
            << strings({"--wedge", "clearcoatRoughness=0,1", "--wedge2", "clearcoat=0,1"}) << QString();
        QTest::newRow("coat roughness, --clearcoat sets one")
            << strings({"--wedge", "clearcoatRoughness=0,1", "--clearcoat", "1"}) << QString();
        QTest::newRow("alpha cutoff on an opaque material (columns)")
            << strings({"--wedge", "roughness=0.5", "--wedge2", "alphaCutoff=0.2,0.8"})
            << QStringLiteral("--wedge2 alphaCutoff sweeps nothing: alphaCutoff is used only with alphaMode");
        QTest::newRow("roughness") << strings({"--wedge", "roughness=0,1"}) << QString();
    }
    void axesThatSweepNothingAreNamed()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, warning);
        const QString out = path(QStringLiteral("nothing.png"));
        const Result r = runFacet(
            QStringList {QStringLiteral("sheet"), QStringLiteral("--cell"), QStringLiteral("16x16"),
                QStringLiteral("--ibl"), QStringLiteral("split-sum"), QStringLiteral("-o"), out}
            + arguments);
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        if (warning.isEmpty())
            QVERIFY2(!r.err.contains(QStringLiteral("sweeps nothing")), qPrintable(describe(r)));
        else
            QVERIFY2(r.err.contains(warning), qPrintable(describe(r)));
    }

    void refusals_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message"); // in stderr
        QTest::newRow("no output") << strings({}) << 2 << QStringLiteral("-o SHEET.png or -o SHEET.exr is required");
        QTest::newRow("bad output type") << strings({"-o", "{dir}/x.jpg"}) << 2 << QStringLiteral("-o '");
        QTest::newRow("bad cell") << strings({"--cell", "0x12", "-o", "{dir}/x.png"}) << 2 << QStringLiteral("--cell: '0x12'");
        QTest::newRow("bad labels") << strings({"--labels", "maybe", "-o", "{dir}/x.png"}) << 2
                                    << QStringLiteral("--labels: 'maybe'");
        QTest::newRow("empty env item") << strings({"--envs", "uniform:1,,uniform:2", "-o", "{dir}/x.png"}) << 2
                                        << QStringLiteral("--envs: ");
        QTest::newRow("unknown wedge parameter") << strings({"--wedge", "shininess=1", "-o", "{dir}/x.png"}) << 2
                                                 << QStringLiteral("--wedge: ");
        QTest::newRow("wedge value out of range") << strings({"--wedge", "roughness=0,2", "-o", "{dir}/x.png"}) << 2
                                                  << QStringLiteral("--wedge: ");
        QTest::newRow("material flag out of range") << strings({"--metallic", "2", "-o", "{dir}/x.png"}) << 2
                                                    << QStringLiteral("--metallic: 2 is outside [0, 1]");
        QTest::newRow("material colour flag") << strings({"--base-color", "1,1", "-o", "{dir}/x.png"}) << 2
                                              << QStringLiteral("--base-color: '1,1' is not r,g,b");
        QTest::newRow("wedge2 alone") << strings({"--wedge2", "metallic=0,1", "-o", "{dir}/x.png"}) << 2
                                      << QStringLiteral("--wedge2 needs --wedge");
        // One --envs environment beside --wedge2 is the sheet's (the README's example); two are columns.
        QTest::newRow("envs and wedge2") << strings({"--wedge", "roughness=0,1", "--wedge2", "metallic=0,1", "--envs",
                                                "uniform:1,sky", "-o", "{dir}/x.png"})
                                         << 2 << QStringLiteral("--envs and --wedge2 both set the columns");
        QTest::newRow("wedge with two materials")
            << strings({"--wedge", "roughness=0,1", "--materials", "gold,copper", "-o", "{dir}/x.png"}) << 2
            << QStringLiteral("--wedge sets the rows");
        QTest::newRow("unknown preset") << strings({"--materials", "gold,unobtainium", "-o", "{dir}/x.png"}) << 1
                                        << QStringLiteral("--materials: 'unobtainium': no preset");
        QTest::newRow("missing material file") << strings({"--materials", "{dir}/nothing.json", "-o", "{dir}/x.png"}) << 1
                                               << QStringLiteral("nothing.json");
        QTest::newRow("missing material in a project")
            << strings({"--materials", "{dir}/lit.json#Steel", "-o", "{dir}/x.png"}) << 1 << QStringLiteral("Steel");
        QTest::newRow("missing environment") << strings({"--envs", "uniform:1,{dir}/nowhere.exr", "-o", "{dir}/x.png"})
                                             << 1 << QStringLiteral("nowhere.exr");
        QStringList golds;
        QStringList uniforms;
        for (int i = 0; i < 17; ++i)
            golds.append(QStringLiteral("gold"));
        for (int i = 0; i < 16; ++i)
            uniforms.append(QStringLiteral("uniform:%1").arg(i + 1));
        QTest::newRow("too many cells") << QStringList {QStringLiteral("--materials"), golds.join(QLatin1Char(',')),
            QStringLiteral("--envs"), uniforms.join(QLatin1Char(',')), QStringLiteral("-o"), QStringLiteral("{dir}/x.png")}
                                        << 2 << QStringLiteral("17 x 16 cells: at most 256");
    }

    void refusals()
    {
        QFETCH(QStringList, arguments);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        for (QString& argument : arguments)
            argument.replace(QLatin1String("{dir}"), m_dir.path());
        // A file already at the output path stays as it was.
        const QString out = path(QStringLiteral("x.png"));
        QVERIFY(facet::test::writeText(out, "previous"));
        const Result r = runFacet(QStringList {QStringLiteral("sheet")} + arguments);
        QVERIFY2(r.exitCode == exitCode, qPrintable(describe(r)));
        QVERIFY2(r.err.contains(message), qPrintable(describe(r)));
        QVERIFY2(r.out.isEmpty(), qPrintable(describe(r)));
        QFile file(out);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), QByteArray("previous"));
    }
};

QTEST_GUILESS_MAIN(SheetCommandTest)
#include "SheetCommandTest.moc"
