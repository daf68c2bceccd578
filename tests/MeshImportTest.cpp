// Assimp import of the CC0 sample meshes, of small files written here with known answers, and
// of broken files, each of which must give a message naming the file and never crash.

#include "MeshTestHelpers.h"

#include <sys/stat.h>

using namespace facet;
using namespace facet::test::mesh;

class MeshImportTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void importSampleMeshes_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("fileVertices");
        QTest::addColumn<int>("triangles");
        QTest::addColumn<QVector<float>>("boundsMinMax");
        // Counts and bounds from the files' glTF accessors (POSITION min/max, index count / 3).
        QTest::newRow("suzi") << QStringLiteral("suzi") << 7503 << 14842
                              << QVector<float> {-0.92973012f, -0.66979480f, -0.54478627f, 0.92973012f,
                                     0.66825354f, 0.57615846f};
        QTest::newRow("bunny") << QStringLiteral("bunny") << 2826 << 5648
                               << QVector<float> {-0.91377079f, -0.89104164f, -0.69637245f, 0.91721433f,
                                      0.93988293f, 0.69886428f};
    }
    void importSampleMeshes()
    {
        QFETCH(QString, name);
        QFETCH(int, fileVertices);
        QFETCH(int, triangles);
        QFETCH(QVector<float>, boundsMinMax);
        const QString path = facet::test::modelPath(name);
        FACET_REQUIRE_ASSET(path, qPrintable(name + QStringLiteral(".glb")));
        std::string error, warning;
        QElapsedTimer timer;
        timer.start();
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        const qint64 ms = timer.elapsed();
        QVERIFY2(mesh, error.c_str());
        qInfo("%s: %d file vertices -> %zu after UV seams, %zu triangles, imported in %lld ms",
            qPrintable(name), fileVertices, mesh->vertices.size(), mesh->triangleCount(), ms);
        QCOMPARE(mesh->triangleCount(), std::size_t(triangles));
        // The fallback splits vertices along chart seams: more than the file's, not absurdly many.
        QVERIFY(mesh->vertices.size() > std::size_t(fileVertices));
        QVERIFY(mesh->vertices.size() < std::size_t(2 * fileVertices));
        QVERIFY(mesh->hasUvs && mesh->uvsGenerated && mesh->hasTangents);
        QVERIFY2(contains(warning, "importMesh: " + path.toStdString() + ": ") && contains(warning, "no UVs"),
            warning.c_str());
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QCOMPARE(mesh->name, name.toStdString());
        QCOMPARE(mesh->subMeshes.size(), std::size_t(1));
        // Not normalised on import: the bounds are the file's.
        for (int k = 0; k < 3; ++k) {
            QVERIFY(std::abs(mesh->bounds.min[k] - boundsMinMax[k]) < 1e-4f);
            QVERIFY(std::abs(mesh->bounds.max[k] - boundsMinMax[3 + k]) < 1e-4f);
        }
        // Outward normals (the file's) and box-projected tangent frames that follow the UVs.
        // Every corner agrees on both files today; 0.1% leaves room for a sliver triangle whose
        // smooth vertex normal leans past its face normal, while a flipped sign or a wrong
        // chart fails by far.
        const FrameAgreement frame = frameAgreement(*mesh);
        qInfo("%s: frame agreement: tangent %.5f, bitangent %.5f, normal %.5f over %zu corners",
            qPrintable(name), frame.tangentFraction(), frame.bitangentFraction(), frame.normalFraction(),
            frame.corners);
        QVERIFY(frame.tangentFraction() > 0.999);
        QVERIFY(frame.bitangentFraction() > 0.999);
        QVERIFY(frame.normalFraction() > 0.999);
        for (const Vertex& v : mesh->vertices)
            QCOMPARE(v.tangent.w, 1.0f); // no box chart is mirrored
        // Framing for the viewer is the caller's step, and works on it.
        Mesh framed = *mesh;
        framed.normalizeToUnitSphere();
        QVERIFY(std::abs(framed.boundingSphereRadius() - 1.0f) < 1e-5f);

        // The spherical fallback also yields a valid frame.
        MeshImportOptions options;
        options.uvFallback = UvProjection::Spherical;
        const std::optional<Mesh> spherical = importMesh(path.toStdString(), &error, &warning, options);
        QVERIFY2(spherical, error.c_str());
        QVERIFY2(spherical->validate(&problem), problem.c_str());
        QVERIFY(contains(warning, "spherical projection"));
    }

    void importFileWithUvs()
    {
        // pmndrs.glb has UVs: they are kept, nothing is generated.
        const QString path = facet::test::modelPath(QStringLiteral("pmndrs"));
        FACET_REQUIRE_ASSET(path, "pmndrs.glb");
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY(mesh->hasUvs && !mesh->uvsGenerated && mesh->hasTangents);
        QCOMPARE(mesh->triangleCount(), std::size_t(1552));
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QVERIFY2(!contains(warning, "UVs"), warning.c_str());
    }

    void importObjTangents()
    {
        // Three quads facing +Z as separate OBJ objects, UVs straight, turned and mirrored
        // (OBJ's UV origin is bottom-left, as ours): the tangents must follow.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("quads.obj"));
        QVERIFY(writeFile(path,
            "# three unit quads facing +Z\n"
            "vn 0 0 1\n"
            "o straight\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
            "o turned\n"
            "v 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\n"
            "vt 0 1\nvt 0 0\nvt 1 0\nvt 1 1\n"
            "f 5/5/1 6/6/1 7/7/1 8/8/1\n"
            "o mirrored\n"
            "v 4 0 0\nv 5 0 0\nv 5 1 0\nv 4 1 0\n"
            "vt 1 0\nvt 0 0\nvt 0 1\nvt 1 1\n"
            "f 9/9/1 10/10/1 11/11/1 12/12/1\n"));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY(mesh->hasUvs && !mesh->uvsGenerated && mesh->hasTangents);
        QCOMPARE(mesh->triangleCount(), std::size_t(6));
        QCOMPARE(mesh->subMeshes.size(), std::size_t(3));
        const std::map<std::string, std::pair<glm::vec3, float>> expected = {{"straight", {{1, 0, 0}, 1.0f}},
            {"turned", {{0, 1, 0}, 1.0f}}, {"mirrored", {{-1, 0, 0}, -1.0f}}};
        for (const SubMesh& sub : mesh->subMeshes) {
            QVERIFY2(expected.count(sub.name), sub.name.c_str());
            const auto& [tangent, w] = expected.at(sub.name);
            QCOMPARE(sub.indexCount, 6u);
            for (uint32_t i = sub.firstIndex; i < sub.firstIndex + sub.indexCount; ++i) {
                const Vertex& v = mesh->vertices[mesh->indices[i]];
                QVERIFY2(glm::length(glm::vec3(v.tangent) - tangent) < 1e-5f, sub.name.c_str());
                QCOMPARE(v.tangent.w, w);
                QVERIFY(glm::length(v.normal - glm::vec3(0, 0, 1)) < 1e-6f);
            }
        }
    }

    void importPartlyWithoutUvs()
    {
        // Two objects, one with UVs and one without: the first keeps its UVs, only the second
        // gets generated ones.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("partial.obj"));
        QVERIFY(writeFile(path,
            "o textured\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0.1 0.2\nvt 0.3 0.2\nvt 0.3 0.4\nf 1/1 2/2 3/3\n"
            "o bare\nv 3 0 0\nv 4 0 0\nv 4 1 0\nf 4 5 6\n"));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QCOMPARE(mesh->subMeshes.size(), std::size_t(2));
        QVERIFY(mesh->hasUvs && mesh->uvsGenerated && mesh->hasTangents);
        QVERIFY2(contains(warning, "1 part(s) without UVs: generated by box projection"), warning.c_str());
        const SubMesh& textured
            = mesh->subMeshes[0].name == "textured" ? mesh->subMeshes[0] : mesh->subMeshes[1];
        const SubMesh& bare = mesh->subMeshes[0].name == "textured" ? mesh->subMeshes[1] : mesh->subMeshes[0];
        QCOMPARE(textured.name, std::string("textured"));
        QCOMPARE(bare.name, std::string("bare"));
        const glm::vec2 fileUvs[3] = {{0.1f, 0.2f}, {0.3f, 0.2f}, {0.3f, 0.4f}};
        for (int k = 0; k < 3; ++k)
            QVERIFY(
                glm::length(mesh->vertices[mesh->indices[textured.firstIndex + uint32_t(k)]].uv - fileUvs[k])
                < 1e-6f);
        // The bare triangle faces +Z: the +Z chart, u along +X, v along +Y.
        const Vertex& a = mesh->vertices[mesh->indices[bare.firstIndex]];
        const Vertex& b = mesh->vertices[mesh->indices[bare.firstIndex + 1]];
        QVERIFY(b.uv.x > a.uv.x && std::abs(b.uv.y - a.uv.y) < 1e-6f);
        const FrameAgreement frame = frameAgreement(*mesh);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
    }

    void importAppliesNodeTransforms()
    {
        // One triangle, instanced by two nodes: a child (translated by (0, 0, 1)) of a parent
        // translated by (10, 20, 30) and scaled by 2, and a node mirrored in X and turned 90
        // degrees about Z. Positions, normals, winding and UVs must come out transformed.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("nodes.gltf"));
        const QJsonArray nodes {
            QJsonObject {{QStringLiteral("name"), QStringLiteral("parent")},
                {QStringLiteral("translation"), QJsonArray {10, 20, 30}},
                {QStringLiteral("scale"), QJsonArray {2, 2, 2}},
                {QStringLiteral("children"), QJsonArray {1}}},
            QJsonObject {{QStringLiteral("name"), QStringLiteral("child")}, {QStringLiteral("mesh"), 0},
                {QStringLiteral("translation"), QJsonArray {0, 0, 1}}},
            // Column-major: x -> (0, -1, 0) after the mirror, y -> (-1, 0, 0): det = -1.
            QJsonObject {{QStringLiteral("name"), QStringLiteral("mirror")}, {QStringLiteral("mesh"), 0},
                {QStringLiteral("matrix"), QJsonArray {0, -1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}},
            // A shear z' = z + x, moved to z = -5: it tilts the triangle's plane, and only the
            // inverse transpose turns the normal with it (the matrix itself leaves +Z alone).
            QJsonObject {{QStringLiteral("name"), QStringLiteral("shear")}, {QStringLiteral("mesh"), 0},
                {QStringLiteral("matrix"), QJsonArray {1, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -5, 1}}},
        };
        QVERIFY(writeFile(path, gltfTriangle(nodes, QJsonArray {0, 2, 3}, true)));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QCOMPARE(mesh->subMeshes.size(), std::size_t(3));
        QCOMPARE(mesh->triangleCount(), std::size_t(3));
        QVERIFY(mesh->hasUvs && !mesh->uvsGenerated && mesh->hasTangents);
        QCOMPARE(mesh->subMeshes[0].name, std::string("tri"));

        const auto corner = [&](std::size_t s, int k) -> const Vertex& {
            return mesh->vertices[mesh->indices[mesh->subMeshes[s].firstIndex + uint32_t(k)]];
        };
        // Instance 1: world = T(10,20,30) S(2) T(0,0,1) p = 2p + (10, 20, 32).
        const glm::vec3 expected1[3] = {{10, 20, 32}, {12, 20, 32}, {10, 22, 32}};
        for (int k = 0; k < 3; ++k) {
            QVERIFY2(
                glm::length(corner(0, k).position - expected1[k]) < 1e-5f, qPrintable(QString::number(k)));
            QVERIFY(glm::length(corner(0, k).normal - glm::vec3(0, 0, 1)) < 1e-6f);
        }
        // glTF's UV origin is top-left; ours (OpenGL) bottom-left: v' = 1 - v.
        QVERIFY(glm::length(corner(0, 0).uv - glm::vec2(0, 1)) < 1e-6f);
        QVERIFY(glm::length(corner(0, 1).uv - glm::vec2(1, 1)) < 1e-6f);
        QVERIFY(glm::length(corner(0, 2).uv - glm::vec2(0, 0)) < 1e-6f);
        // u grows along +X; glTF's v grows along +Y, so ours along -Y: a mirrored chart (w = -1).
        QVERIFY(glm::length(glm::vec3(corner(0, 0).tangent) - glm::vec3(1, 0, 0)) < 1e-5f);
        QCOMPARE(corner(0, 0).tangent.w, -1.0f);

        // Instance 2: p -> (-y, -x, z). The winding is reversed, so the face still agrees with
        // the transformed normal, which stays +Z (the inverse transpose of this matrix).
        const glm::vec3 positions2[3] = {{0, 0, 0}, {0, -1, 0}, {-1, 0, 0}};
        for (int k = 0; k < 3; ++k) {
            const auto found = std::find_if(mesh->vertices.begin(), mesh->vertices.end(),
                [&](const Vertex& v) { return glm::length(v.position - positions2[k]) < 1e-6f; });
            QVERIFY2(found != mesh->vertices.end(), qPrintable(QString::number(k)));
            QVERIFY(glm::length(found->normal - glm::vec3(0, 0, 1)) < 1e-6f);
        }
        // Instance 3: (x, y, z) -> (x, y, z + x - 5); normal along (-1, 0, 1).
        const glm::vec3 positions3[3] = {{0, 0, -5}, {1, 0, -4}, {0, 1, -5}};
        for (int k = 0; k < 3; ++k) {
            QVERIFY(glm::length(corner(2, k).position - positions3[k]) < 1e-6f);
            QVERIFY(glm::length(corner(2, k).normal - glm::normalize(glm::vec3(-1, 0, 1))) < 1e-6f);
        }
        const FrameAgreement frame = frameAgreement(*mesh);
        QCOMPARE(frame.corners, std::size_t(9));
        QCOMPARE(frame.normalAgrees, frame.corners);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
    }

    void importKeepsFileTangents()
    {
        // The file's TANGENTs (deliberately not what generateTangents() would make from the UVs,
        // (1, 0, 0, -1) everywhere) are kept, turned by the node's rotation: 90 degrees about +Z,
        // (x, y) -> (-y, x).
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("tangents.gltf"));
        const QJsonArray nodes {QJsonObject {{QStringLiteral("mesh"), 0},
            {QStringLiteral("rotation"), QJsonArray {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}}};
        QVERIFY(writeFile(path, gltfTriangle(nodes, QJsonArray {0}, true, true)));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY(mesh->hasTangents && !mesh->uvsGenerated);
        const glm::vec3 expected[3] = {{-0.8f, 0.6f, 0.0f}, {-0.6f, 0.8f, 0.0f}, {-1.0f, 0.0f, 0.0f}};
        QCOMPARE(mesh->indices.size(), std::size_t(3));
        for (int k = 0; k < 3; ++k) {
            const Vertex& v = mesh->vertices[mesh->indices[std::size_t(k)]];
            QVERIFY2(glm::length(glm::vec3(v.tangent) - expected[k]) < 1e-5f,
                qPrintable(QStringLiteral("%1 %2 %3").arg(v.tangent.x).arg(v.tangent.y).arg(v.tangent.z)));
            QCOMPARE(v.tangent.w, -1.0f);
        }
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
    }

    void importGeneratesMissingNormals()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("no-normals.gltf"));
        const QJsonArray nodes {QJsonObject {{QStringLiteral("mesh"), 0}}};
        QVERIFY(writeFile(path, gltfTriangle(nodes, QJsonArray {0}, false)));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QVERIFY2(contains(warning, "no normals"), warning.c_str());
        for (const Vertex& v : mesh->vertices)
            QVERIFY(glm::length(v.normal - glm::vec3(0, 0, 1)) < 1e-6f);
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
    }

    void importDropsPointsAndLines()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("mixed.obj"));
        QVERIFY(writeFile(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\nl 1 4\np 4\n"));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(path.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QCOMPARE(mesh->triangleCount(), std::size_t(1));
        QVERIFY2(contains(warning, "2 part(s) made of points or lines dropped"), warning.c_str());
        // Only points and lines: nothing to show.
        const QString onlyLines = dir.filePath(QStringLiteral("lines.obj"));
        QVERIFY(writeFile(onlyLines, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n"));
        checkImportFails(onlyLines, "no triangles");
    }

    void importLimits()
    {
        const QString path = facet::test::modelPath(QStringLiteral("suzi"));
        FACET_REQUIRE_ASSET(path, "suzi.glb");
        MeshImportOptions options;
        options.maxVertices = 1000;
        std::string error;
        QVERIFY(!importMesh(path.toStdString(), &error, nullptr, options));
        // The message names the file, the part (Draco-compressed in the sample), the count and the limit.
        QVERIFY2(contains(error, "importMesh: " + path.toStdString() + ": ")
                && contains(error, "7503 vertices") && contains(error, "1000"),
            error.c_str());
        options = {};
        options.maxTriangles = 100;
        QVERIFY(!importMesh(path.toStdString(), &error, nullptr, options));
        QVERIFY2(contains(error, "14842 triangles"), error.c_str());
    }

    void importBadFiles()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        checkImportFails(dir.filePath(QStringLiteral("nothing-here.glb")), "does not exist");
        checkImportFails(dir.path(), "is a directory");
        std::string error;
        QVERIFY(!importMesh("", &error, nullptr));
        QVERIFY2(contains(error, "importMesh: : no file name"), error.c_str());

        const QString empty = dir.filePath(QStringLiteral("empty.obj"));
        QVERIFY(writeFile(empty, {}));
        checkImportFails(empty, "file is empty");

        const QString garbage = dir.filePath(QStringLiteral("garbage.obj"));
        QVERIFY(writeFile(
            garbage, "This is not a mesh.\nJust some text pretending to be an OBJ file.\n\x01\x02\x03\n"));
        checkImportFails(garbage, "no meshes");

        const QString notAMesh = dir.filePath(QStringLiteral("picture.png"));
        QVERIFY(writeFile(notAMesh, QByteArray("\x89PNG\r\n\x1a\n", 8) + QByteArray(64, '\0')));
        checkImportFails(notAMesh, "Assimp cannot read it");

        const QString ply = dir.filePath(QStringLiteral("bad-indices.ply"));
        QVERIFY(writeFile(ply,
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
        checkImportFails(ply, "out of range");
        // Assimp 5.2 hangs on a PLY header without "end_header": cut short, or the keyword damaged.
        const QByteArray plyText = readFile(ply);
        const QString cutPly = dir.filePath(QStringLiteral("cut.ply"));
        QVERIFY(writeFile(cutPly, plyText.left(plyText.indexOf("end_header") + 5)));
        checkImportFails(cutPly, "no \"end_header\" line");
        QVERIFY(writeFile(cutPly, plyText.left(plyText.indexOf("end_header") + 10))); // no newline
        checkImportFails(cutPly, "no \"end_header\" line");
        const QString damagedPly = dir.filePath(QStringLiteral("damaged.ply"));
        QVERIFY(writeFile(damagedPly,
            QByteArray(plyText).replace("end_header",
                "end_\xb8"
                "eader")));
        checkImportFails(damagedPly, "no \"end_header\" line");
        // A face list cut short leaves a face with no indices, which Assimp 5.2 validates but
        // then asserts on (an abort in Debian's build).
        const QString emptyFace = dir.filePath(QStringLiteral("empty-face.ply"));
        QVERIFY(writeFile(emptyFace, plyText.left(plyText.lastIndexOf("3 0 1 7")) + "0"));
        checkImportFails(emptyFace, "face 0 of mesh 0 has no vertices");
        const QString notPly = dir.filePath(QStringLiteral("not-really.ply"));
        QVERIFY(writeFile(notPly, "solid nothing\nendsolid nothing\n"));
        checkImportFails(notPly, "not a PLY file");

        const QString sample = facet::test::modelPath(QStringLiteral("suzi"));
        if (!sample.isEmpty()) {
            // The real file cut in half, and cut at a few other places (header, JSON, binary).
            const QByteArray whole = readFile(sample);
            QVERIFY(whole.size() > 1000);
            for (qsizetype cut :
                {whole.size() / 2, qsizetype(12), qsizetype(20), qsizetype(100), whole.size() - 1}) {
                const QString truncated = dir.filePath(QStringLiteral("truncated-%1.glb").arg(cut));
                QVERIFY(writeFile(truncated, whole.left(cut)));
                checkImportFails(truncated, "");
                if (QTest::currentTestFailed())
                    return;
            }
            // Flipped bytes in the compressed payload: fails or succeeds, never crashes; a mesh
            // that comes back is valid.
            QByteArray corrupt = whole;
            for (qsizetype i = corrupt.size() / 3; i < corrupt.size(); i += 997)
                corrupt[i] = char(corrupt[i] ^ 0x5a);
            const QString corrupted = dir.filePath(QStringLiteral("corrupted.glb"));
            QVERIFY(writeFile(corrupted, corrupt));
            std::string warning;
            if (const std::optional<Mesh> mesh = importMesh(corrupted.toStdString(), &error, &warning)) {
                std::string problem;
                QVERIFY2(mesh->validate(&problem), problem.c_str());
            } else {
                QVERIFY2(contains(error, corrupted.toStdString()), error.c_str());
            }
        }

        // A file we may not read (only meaningful when not running as root).
        const QString locked = dir.filePath(QStringLiteral("locked.obj"));
        QVERIFY(writeFile(locked, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
        QFile::setPermissions(locked, QFileDevice::Permissions());
        QFile probe(locked);
        if (!probe.open(QIODevice::ReadOnly))
            checkImportFails(locked, "cannot be read");
    }

    // Inputs that hung or read without end before they were refused (issue 12's hostile inputs):
    // each must fail fast, naming the file and the reason. A hang shows as the test's timeout.
    void refusedBeforeReading_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("reason");
        QTest::newRow("ASCII PLY of 210 bytes claiming 10M vertices") << QStringLiteral(
            "huge-ascii-ply") << QStringLiteral("declares 10000000 vertex, 1 face elements");
        QTest::newRow("binary PLY claiming 1M faces")
            << QStringLiteral("huge-binary-ply") << QStringLiteral("bytes follow the header");
        // Issue 29: a face's list count of 300 million took 2.4 GB and 14 s before Assimp refused.
        QTest::newRow("binary PLY, a list of 300M (uint count, little-endian)")
            << QStringLiteral("list-uint-le-ply") << QStringLiteral("face 0 has a list of 300000000 values");
        QTest::newRow("binary PLY, a list of 300M (int count, big-endian)")
            << QStringLiteral("list-int-be-ply") << QStringLiteral("face 0 has a list of 300000000 values");
        QTest::newRow("binary PLY, a negative list count")
            << QStringLiteral("list-negative-ply") << QStringLiteral("a negative or non-integer number of");
        QTest::newRow("binary PLY, the second face's list past the end")
            << QStringLiteral("list-second-ply") << QStringLiteral("face 1 has a list of 200 values");
        QTest::newRow("a FIFO") << QStringLiteral("fifo") << QStringLiteral("is not a regular file");
        QTest::newRow("a link to /dev/zero")
            << QStringLiteral("zero") << QStringLiteral("is not a regular file");
        QTest::newRow("a link loop") << QStringLiteral("loop") << QStringLiteral("loop of symbolic links");
    }

    void refusedBeforeReading()
    {
        QFETCH(QString, kind);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        const QString path = dir.filePath(
            kind + (kind.endsWith(QLatin1String("ply")) ? QStringLiteral(".ply") : QStringLiteral(".obj")));
        const QByteArray vertexProperties = "property float x\nproperty float y\nproperty float z\n";
        if (kind == QLatin1String("huge-ascii-ply")) {
            const QByteArray text = "ply\nformat ascii 1.0\nelement vertex 10000000\n" + vertexProperties
                + "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 "
                  "0\n3 0 1 2\n";
            QVERIFY(text.size() < 256);
            QVERIFY(writeFile(path, text));
        } else if (kind == QLatin1String("huge-binary-ply")) {
            QVERIFY(writeFile(path,
                "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + vertexProperties
                    + "element face 1000000\nproperty list uchar int vertex_indices\nend_header\n"
                    + QByteArray(36 + 13, '\0')));
        } else if (kind.startsWith(QLatin1String("list-"))) {
            // Three vertices (36 bytes), then faces whose list counts are given as bytes.
            const bool bigEndian = kind == QLatin1String("list-int-be-ply");
            const QByteArray countType = kind == QLatin1String("list-uint-le-ply") ? "uint" : "int";
            const auto count = [bigEndian](std::uint32_t v) {
                QByteArray b(4, '\0');
                for (int i = 0; i < 4; ++i)
                    b[bigEndian ? 3 - i : i] = char((v >> (8 * i)) & 0xFF);
                return b;
            };
            QByteArray faces;
            const QByteArray triangle = count(0) + count(1) + count(2);
            if (kind == QLatin1String("list-second-ply"))
                faces = count(3) + triangle + count(200) + triangle;
            else if (kind == QLatin1String("list-negative-ply"))
                faces = count(0xFFFFFFF0u) + triangle + count(3) + triangle;
            else
                faces = count(300000000u) + triangle + count(3) + triangle;
            QVERIFY(writeFile(path,
                "ply\nformat " + QByteArray(bigEndian ? "binary_big_endian" : "binary_little_endian")
                    + " 1.0\nelement vertex 3\n" + vertexProperties + "element face 2\nproperty list "
                    + countType + " int vertex_indices\nend_header\n" + QByteArray(36, '\0') + faces));
        } else if (kind == QLatin1String("fifo")) {
            QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        } else if (kind == QLatin1String("zero")) {
            QVERIFY(QFile::link(QStringLiteral("/dev/zero"), path));
        } else {
            QVERIFY(QFile::link(path, path));
        }
        QElapsedTimer clock;
        clock.start();
        checkImportFails(path, qPrintable(reason));
        QVERIFY2(clock.elapsed() < facet::test::wallClockBoundMs(5000),
            qPrintable(QStringLiteral("%1 ms").arg(clock.elapsed())));
    }

    // An OBJ whose material library is a FIFO: fopen would block the import for ever. The
    // library is treated as missing (Assimp's warning) and the mesh loads.
    void objMaterialLibraryThatIsAFifo()
    {
        QTemporaryDir dir;
        QCOMPARE(::mkfifo(QFile::encodeName(dir.filePath(QStringLiteral("pipe.mtl"))).constData(), 0600), 0);
        const QString obj = dir.filePath(QStringLiteral("model.obj"));
        QVERIFY(writeFile(
            obj, "mtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"));
        std::string error, warning;
        const std::optional<Mesh> mesh = importMesh(obj.toStdString(), &error, &warning);
        QVERIFY2(mesh, error.c_str());
        QCOMPARE(mesh->vertices.size(), std::size_t(3));
    }

    void importableMeshPatternsListsCommonFormats()
    {
        const std::string patterns = importableMeshPatterns();
        for (const char* pattern : {"*.obj", "*.gltf", "*.glb", "*.fbx", "*.ply", "*.dae", "*.stl"})
            QVERIFY2(contains(patterns, pattern), pattern);
    }
};

QTEST_GUILESS_MAIN(MeshImportTest)
#include "MeshImportTest.moc"
