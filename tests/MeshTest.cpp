// Meshes: the procedural primitives (valid, watertight, outward, the right volume, tangent
// frames that agree with their UVs), normalisation, transforms, tangent and UV generation.
// Import is tested in MeshImportTest.

#include "MeshTestHelpers.h"

using namespace facet;
using namespace facet::test::mesh;

class MeshTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
private Q_SLOTS:
    // ---- Primitives ---------------------------------------------------------------------
    void primitives_data()
    {
        QTest::addColumn<QString>("name");
        for (std::string_view name : primitiveNames())
            QTest::newRow(std::string(name).c_str())
                << QString::fromLatin1(name.data(), qsizetype(name.size()));
    }
    void primitives()
    {
        QFETCH(QString, name);
        const std::optional<Mesh> mesh = makePrimitive(name.toStdString());
        QVERIFY(mesh);
        std::string problem;
        QVERIFY2(mesh->validate(&problem), problem.c_str());
        QCOMPARE(mesh->name, name.toStdString());
        QVERIFY(mesh->hasUvs && mesh->hasTangents && !mesh->uvsGenerated);
        QCOMPARE(mesh->subMeshes.size(), std::size_t(1));
        QCOMPARE(mesh->subMeshes[0].firstIndex, 0u);
        QCOMPARE(std::size_t(mesh->subMeshes[0].indexCount), mesh->indices.size());
        QVERIFY(mesh->triangleCount() > 0);
        // No primitive has a mirrored UV chart.
        for (const Vertex& v : mesh->vertices)
            QCOMPARE(v.tangent.w, 1.0f);
        // Every corner's frame agrees with its triangle: tangent along dP/du, bitangent along
        // dP/dv, normal on the outward side. Analytic frames on these shapes agree everywhere.
        const FrameAgreement frame = frameAgreement(*mesh);
        QVERIFY(frame.corners >= 3 * mesh->triangleCount() - 3); // at most one UV-degenerate triangle
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        QCOMPARE(frame.normalAgrees, frame.corners);
        if (isClosedPrimitive(name.toStdString())) {
            QString why;
            QVERIFY2(isClosed(*mesh, &why), qPrintable(why));
            QVERIFY(signedVolume(*mesh) > 0.0);
        }
        // Framing puts the bounding sphere at the origin with radius 1.
        Mesh framed = *mesh;
        framed.normalizeToUnitSphere();
        QVERIFY2(framed.validate(&problem), problem.c_str());
        QVERIFY(std::abs(framed.boundingSphereRadius() - 1.0f) < 1e-5f);
        QVERIFY(glm::length(framed.bounds.center()) < 1e-5f);
        for (const Vertex& v : framed.vertices)
            QVERIFY(glm::length(v.position) <= 1.0f + 1e-5f);
    }

    void primitiveVolumes()
    {
        // Inscribed polyhedra fall short of the smooth shape by O(1/segments^2): with 64
        // segments about 0.3% for the sphere; the brief's bound is 1%.
        const double sphere = signedVolume(makeSphere());
        QVERIFY2(std::abs(sphere / (4.0 / 3.0 * kPi) - 1.0) < 0.01, qPrintable(QString::number(sphere)));
        QVERIFY(sphere < 4.0 / 3.0 * kPi); // inscribed: never larger
        QVERIFY(std::abs(signedVolume(makeCube()) - 8.0) < 1e-5);
        QVERIFY(std::abs(signedVolume(makeCylinder()) / (2.0 * kPi) - 1.0) < 0.01);
        const double torus = 2.0 * kPi * kPi * 0.7 * 0.3 * 0.3; // 2 pi^2 R r^2
        QVERIFY(std::abs(signedVolume(makeTorus()) / torus - 1.0) < 0.01);
        // The shader ball: a bit less than its ball (the band's recess) plus the base and neck.
        const double ball = 4.0 / 3.0 * kPi * 0.8 * 0.8 * 0.8;
        const double shaderBall = signedVolume(makeShaderBall());
        QVERIFY2(
            shaderBall > 0.85 * ball && shaderBall < 1.15 * ball, qPrintable(QString::number(shaderBall)));
    }

    void sphereLayout()
    {
        const Mesh sphere = makeSphere();
        QCOMPARE(sphere.vertices.size(), std::size_t(2 * 64 + 31 * 65));
        QCOMPARE(sphere.triangleCount(), std::size_t(2 * 64 + 2 * 64 * 30));
        for (const Vertex& v : sphere.vertices) {
            QVERIFY(std::abs(glm::length(v.position) - 1.0f) < 1e-6f);
            QVERIFY(glm::length(v.normal - v.position) < 1e-6f); // analytic normals
            // u = 0.5 - atan2(z, x) / (2 pi) (the seam column repeats u = 0 as u = 1), v = asin(y) / pi + 0.5
            const bool pole = std::abs(v.position.y) > 1.0f - 1e-6f;
            if (!pole) {
                const double u = 0.5 - std::atan2(double(v.position.z), double(v.position.x)) / (2.0 * kPi);
                const double du = std::abs(u - double(v.uv.x));
                QVERIFY2(du < 1e-5 || std::abs(du - 1.0) < 1e-5, qPrintable(QString::number(du)));
            }
            QVERIFY(std::abs(std::asin(double(v.position.y)) / kPi + 0.5 - double(v.uv.y)) < 1e-5);
        }
        // Seen from the reference camera on +Z, u grows to the right (+X) and v up: not mirrored.
        const auto front = std::min_element(
            sphere.vertices.begin(), sphere.vertices.end(), [](const Vertex& a, const Vertex& b) {
                return glm::length(a.position - glm::vec3(0, 0, 1))
                    < glm::length(b.position - glm::vec3(0, 0, 1));
            });
        QVERIFY(glm::length(front->position - glm::vec3(0, 0, 1)) < 1e-6f);
        QVERIFY(glm::length(glm::vec3(front->tangent) - glm::vec3(1, 0, 0)) < 1e-6f);
        QCOMPARE(front->uv.x, 0.25f);
    }

    void primitiveArguments()
    {
        QVERIFY(!makePrimitive("teapot"));
        QVERIFY(!makePrimitive(""));
        QVERIFY(!makePrimitive("Sphere"));
        QCOMPARE(primitiveNames().size(), std::size_t(6));
        // Out-of-range tessellation is clamped, never a crash or a broken mesh.
        for (const Mesh& mesh : {makeSphere(0, -5), makeSphere(3, 2), makeCylinder(-1), makeTorus(1, 1),
                 makeShaderBall(2), makePlane(0), makeSphere(100000, 3)}) {
            std::string problem;
            QVERIFY2(mesh.validate(&problem), problem.c_str());
            if (mesh.name != "plane") {
                QString why;
                QVERIFY2(isClosed(mesh, &why),
                    qPrintable(QString::fromStdString(mesh.name) + QLatin1String(": ") + why));
            }
        }
        QCOMPARE(makeSphere(100000, 3).vertices.size(), makeSphere(4096, 3).vertices.size());
        QCOMPARE(makePlane(4).triangleCount(), std::size_t(32));
        QCOMPARE(makeCube().vertices.size(), std::size_t(24));
    }

    // ---- Mesh ---------------------------------------------------------------------------
    void normalizeToUnitSphere()
    {
        Mesh mesh = makeTorus();
        QVERIFY(mesh.transform(glm::mat4 {{3, 0, 0, 0}, {0, 0.5f, 0, 0}, {0, 0, 2, 0}, {10, -4, 7, 1}}));
        const Mesh before = mesh;
        const glm::mat4 applied = mesh.normalizeToUnitSphere();
        QVERIFY(std::abs(mesh.boundingSphereRadius() - 1.0f) < 1e-5f);
        QVERIFY(glm::length(mesh.bounds.center()) < 1e-5f);
        // The returned transform is what was applied.
        for (std::size_t i = 0; i < mesh.vertices.size(); i += 97) {
            const glm::vec3 expected = glm::vec3(applied * glm::vec4(before.vertices[i].position, 1.0f));
            QVERIFY(glm::length(expected - mesh.vertices[i].position) < 1e-5f);
            QCOMPARE(mesh.vertices[i].normal, before.vertices[i].normal);
        }
        // Idempotent.
        const glm::mat4 again = mesh.normalizeToUnitSphere();
        for (int c = 0; c < 4; ++c)
            QVERIFY(glm::length(again[c] - glm::mat4(1.0f)[c]) < 1e-5f);
        // Degenerate meshes: empty is left alone, a single point is only centred.
        Mesh empty;
        QCOMPARE(empty.normalizeToUnitSphere(), glm::mat4(1.0f));
        Mesh point;
        point.vertices.resize(2);
        point.vertices[0].position = point.vertices[1].position = {1, 2, 3};
        const glm::mat4 centred = point.normalizeToUnitSphere();
        QCOMPARE(point.vertices[0].position, glm::vec3(0.0f));
        QCOMPARE(glm::vec3(centred[3]), glm::vec3(-1, -2, -3));
    }

    void transform()
    {
        // Non-uniform scale: normals must stay perpendicular to the surface (inverse transpose).
        Mesh sphere = makeSphere(32, 16);
        QVERIFY(sphere.transform(glm::mat4 {{2, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0.5f, 0}, {0, 0, 0, 1}}));
        std::string problem;
        QVERIFY2(sphere.validate(&problem), problem.c_str());
        FrameAgreement frame = frameAgreement(sphere);
        QCOMPARE(frame.normalAgrees, frame.corners);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        // Ellipsoid normal at (x, y, z) is along (x/a^2, y/b^2, z/c^2).
        for (const Vertex& v : sphere.vertices) {
            const glm::vec3 expected = glm::normalize(v.position / glm::vec3(4.0f, 1.0f, 0.25f));
            QVERIFY(glm::length(v.normal - expected) < 1e-5f);
        }
        // A mirror keeps the mesh outward (winding reversed) and flips the handedness.
        Mesh mirrored = makeCube();
        QVERIFY(mirrored.transform(glm::mat4 {{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
        QVERIFY2(mirrored.validate(&problem), problem.c_str());
        QVERIFY(std::abs(signedVolume(mirrored) - 8.0) < 1e-5);
        frame = frameAgreement(mirrored);
        QCOMPARE(frame.normalAgrees, frame.corners);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        for (const Vertex& v : mirrored.vertices)
            QCOMPARE(v.tangent.w, -1.0f);
        // Singular and non-finite matrices are refused and leave the mesh alone.
        Mesh cube = makeCube();
        QVERIFY(
            !cube.transform(glm::mat4 {{1, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, &problem));
        QVERIFY2(contains(problem, "Mesh::transform: 'cube'"), problem.c_str());
        QVERIFY(!cube.transform(glm::mat4(std::nanf(""))));
        QVERIFY(cube == makeCube());
    }

    void validateCatchesBrokenMeshes()
    {
        const Mesh good = makeCube();
        const auto expectProblem = [&](Mesh broken, const char* part) {
            std::string problem;
            QVERIFY(!broken.validate(&problem));
            QVERIFY2(contains(problem, "Mesh::validate: 'cube': "), problem.c_str());
            QVERIFY2(contains(problem, part), problem.c_str());
        };
        Mesh m = good;
        m.indices[5] = 24;
        expectProblem(m, "out of range");
        m = good;
        m.indices.pop_back();
        expectProblem(m, "not a multiple of 3");
        m = good;
        m.vertices[3].position.x = std::nanf("");
        expectProblem(m, "vertex 3: position is not finite");
        m = good;
        m.vertices[4].normal *= 1.1f;
        expectProblem(m, "vertex 4: normal");
        m = good;
        m.vertices[5].tangent = glm::vec4(
            glm::normalize(glm::vec3(m.vertices[5].normal) + glm::vec3(m.vertices[5].tangent)), 1.0f);
        expectProblem(m, "not perpendicular");
        m = good;
        m.vertices[6].tangent.w = 0.5f;
        expectProblem(m, "handedness");
        m = good;
        m.subMeshes[0].indexCount += 3;
        expectProblem(m, "sub-mesh 0");
        m = good;
        m.vertices[7].position *= 2.0f; // bounds not updated
        expectProblem(m, "outside the bounds");
        m = good;
        m.vertices[8].uv.y = INFINITY;
        expectProblem(m, "UV is not finite");
        // Tangents are only checked when the mesh says it has them.
        m = good;
        m.vertices[6].tangent.w = 0.5f;
        m.hasTangents = false;
        QVERIFY(m.validate());
    }

    // ---- Tangents -----------------------------------------------------------------------
    void tangentsFromUvs()
    {
        // A quad in the XY plane facing +Z, UVs in three layouts: straight (u = +X, v = +Y),
        // turned a quarter (u = +Y, v = -X), mirrored (u = -X, v = +Y).
        const std::vector<glm::vec3> quad
            = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        const struct {
            std::vector<glm::vec2> uvs;
            glm::vec3 tangent;
            float w;
        } cases[] = {
            {{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}, {1, 0, 0}, 1.0f},
            {{{0, 1}, {0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}}, {0, 1, 0}, 1.0f},
            {{{1, 0}, {0, 0}, {0, 1}, {1, 0}, {0, 1}, {1, 1}}, {-1, 0, 0}, -1.0f},
        };
        for (const auto& c : cases) {
            Mesh mesh = triangles(quad, c.uvs);
            TangentStats stats;
            std::string problem;
            QVERIFY2(generateTangents(mesh, &problem, &stats), problem.c_str());
            QVERIFY(mesh.hasTangents);
            QCOMPARE(stats.degenerateTriangles, std::size_t(0));
            QCOMPARE(stats.fallbackVertices, std::size_t(0));
            for (const Vertex& v : mesh.vertices) {
                QVERIFY(glm::length(glm::vec3(v.tangent) - c.tangent) < 1e-6f);
                QCOMPARE(v.tangent.w, c.w);
            }
            QVERIFY2(mesh.validate(&problem), problem.c_str());
        }
        // At a shared vertex each triangle votes with its dP/du DIRECTION weighted by its corner
        // angle, not with dP/du's length (as MikkTSpace): triangle (O, A, B) has dP/du = +X and
        // a 90 degree corner at O; triangle (O, B, C) has dP/du = (100, -200, 0) from its
        // squeezed UVs and a 45 degree corner. O's tangent is their angle-weighted mean direction.
        {
            Mesh fan;
            fan.name = "fan";
            const glm::vec3 positions[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 1, 0}};
            const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {0, 1}, {-0.01f, -1.0f}};
            for (int i = 0; i < 4; ++i) {
                Vertex v;
                v.position = positions[i];
                v.normal = {0, 0, 1};
                v.uv = uvs[i];
                fan.vertices.push_back(v);
            }
            fan.indices = {0, 1, 2, 0, 2, 3};
            fan.hasUvs = true;
            QVERIFY(generateTangents(fan));
            const glm::vec3 expected = glm::normalize(
                float(kPi / 2) * glm::vec3(1, 0, 0) + float(kPi / 4) * glm::normalize(glm::vec3(1, -2, 0)));
            QVERIFY2(angleDegrees(glm::vec3(fan.vertices[0].tangent), expected) < 0.01,
                qPrintable(QString::number(angleDegrees(glm::vec3(fan.vertices[0].tangent), expected))));
            QCOMPARE(fan.vertices[0].tangent.w, 1.0f);
        }
        // No UV area: an arbitrary unit tangent perpendicular to the normal (Duff et al.).
        Mesh flat = triangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}});
        TangentStats stats;
        QVERIFY(generateTangents(flat, nullptr, &stats));
        QCOMPARE(stats.degenerateTriangles, std::size_t(1));
        QCOMPARE(stats.fallbackVertices, std::size_t(3));
        std::string problem;
        QVERIFY2(flat.validate(&problem), problem.c_str());
        // Without UVs it refuses, naming the mesh.
        Mesh noUvs = makeCube();
        noUvs.hasUvs = false;
        QVERIFY(!generateTangents(noUvs, &problem));
        QVERIFY2(
            contains(problem, "generateTangents: 'cube': ") && contains(problem, "no UVs"), problem.c_str());
        Mesh badIndex = makeCube();
        badIndex.indices[0] = 1000;
        QVERIFY(!generateTangents(badIndex, &problem));
        QVERIFY2(contains(problem, "out of range"), problem.c_str());
    }

    void perpendicularTangentIsOrthonormal()
    {
        // Every direction, including the poles and the n.z = 0 circle where the basis switches.
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j < 80; ++j) {
                const double theta = kPi * i / 40.0, phi = 2.0 * kPi * j / 80.0;
                const glm::vec3 n(
                    std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
                const glm::vec3 t = perpendicularTangent(n);
                QVERIFY(std::abs(glm::length(t) - 1.0f) < 1e-5f);
                QVERIFY(std::abs(glm::dot(t, n)) < 1e-5f);
            }
    }

    void generatedTangentsMatchAnalytic()
    {
        // The generator, run on primitives whose exact tangents are known, must reproduce them.
        // Where a vertex has triangles on both sides the chord directions average back to the
        // exact tangent; on the u = 0/1 seam it has them on one side only and is off by half a
        // segment (360 / 64 / 2 = 2.8 degrees on the sphere): hence worst < 3, mean < 0.5.
        for (const Mesh& reference : {makeSphere(), makeShaderBall(), makeTorus(), makeCube()}) {
            Mesh mesh = reference;
            for (Vertex& v : mesh.vertices)
                v.tangent = {0, 0, 0, 0};
            TangentStats stats;
            QVERIFY(generateTangents(mesh, nullptr, &stats));
            QCOMPARE(stats.fallbackVertices, std::size_t(0));
            double worst = 0.0, sum = 0.0;
            for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
                const double angle = angleDegrees(
                    glm::vec3(mesh.vertices[i].tangent), glm::vec3(reference.vertices[i].tangent));
                worst = std::max(worst, angle);
                sum += angle;
                QCOMPARE(mesh.vertices[i].tangent.w, reference.vertices[i].tangent.w);
            }
            const double mean = sum / double(mesh.vertices.size());
            qInfo("%s: generated vs analytic tangents: worst %.3g, mean %.3g degrees", reference.name.c_str(),
                worst, mean);
            QVERIFY2(worst < 3.0 && mean < 0.5, reference.name.c_str());
        }
    }

    // ---- UV fallback --------------------------------------------------------------------
    void boxProjection()
    {
        // The sphere without UVs: box projection puts each triangle in one chart, splits the
        // vertices between charts, and gives w = +1 tangents that agree with the UVs.
        Mesh mesh = makeSphere();
        mesh.hasUvs = mesh.hasTangents = false;
        const std::size_t before = mesh.vertices.size();
        std::string problem;
        QVERIFY2(ensureTangentFrame(mesh, UvProjection::Box, &problem), problem.c_str());
        QVERIFY(mesh.hasUvs && mesh.uvsGenerated && mesh.hasTangents);
        QVERIFY(mesh.vertices.size() > before);
        QVERIFY2(mesh.validate(&problem), problem.c_str());
        const auto& faces = boxProjectionFaces();
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            // Which chart the face normal picks; every corner's UV is that chart's projection.
            const glm::vec3 p0 = mesh.vertices[mesh.indices[t]].position;
            const glm::vec3 n = glm::cross(mesh.vertices[mesh.indices[t + 1]].position - p0,
                mesh.vertices[mesh.indices[t + 2]].position - p0);
            const auto chart
                = std::max_element(faces.begin(), faces.end(), [&](const BoxFace& a, const BoxFace& b) {
                      return glm::dot(a.normal, n) < glm::dot(b.normal, n);
                  });
            for (int k = 0; k < 3; ++k) {
                const Vertex& v = mesh.vertices[mesh.indices[t + k]];
                const glm::vec2 expected(0.5f + 0.5f * glm::dot(v.position, chart->tangent),
                    0.5f + 0.5f * glm::dot(v.position, chart->bitangent));
                QVERIFY(glm::length(v.uv - expected) < 1e-5f);
            }
        }
        for (const Vertex& v : mesh.vertices)
            QCOMPARE(v.tangent.w, 1.0f);
        const FrameAgreement frame = frameAgreement(mesh);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        QVERIFY2(frame.tangentFraction() > 0.999, qPrintable(QString::number(frame.tangentFraction())));
        // Splitting keeps the surface closed.
        QString why;
        QVERIFY2(isClosed(mesh, &why), qPrintable(why));
    }

    void sphericalProjection()
    {
        // On the sphere itself the spherical fallback reproduces the primitive's own UVs
        // (up to the seam's u + 1 and the poles' mid-segment u) and no triangle spans the seam.
        const Mesh reference = makeSphere();
        Mesh mesh = reference;
        mesh.hasUvs = mesh.hasTangents = false;
        for (Vertex& v : mesh.vertices)
            v.uv = {-7, -7};
        std::string problem;
        QVERIFY2(generateUvs(mesh, UvProjection::Spherical, &problem), problem.c_str());
        QVERIFY(mesh.uvsGenerated && !mesh.hasTangents);
        QVERIFY2(generateTangents(mesh, &problem), problem.c_str());
        QVERIFY2(mesh.validate(&problem), problem.c_str());
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            float lo = 10, hi = -10;
            for (int k = 0; k < 3; ++k) {
                const Vertex& v = mesh.vertices[mesh.indices[t + k]];
                lo = std::min(lo, v.uv.x);
                hi = std::max(hi, v.uv.x);
                QVERIFY(std::abs(std::asin(v.position.y) / float(kPi) + 0.5f - v.uv.y) < 1e-5f);
            }
            QVERIFY2(hi - lo < 1.5f / 64.0f,
                qPrintable(QStringLiteral("triangle %1 spans u %2..%3").arg(t / 3).arg(lo).arg(hi)));
        }
        for (std::size_t i = 0; i < reference.vertices.size(); ++i) {
            const float du = std::abs(mesh.vertices[i].uv.x - reference.vertices[i].uv.x);
            QVERIFY(du < 1e-5f || std::abs(du - 1.0f) < 1e-5f);
        }
        const FrameAgreement frame = frameAgreement(mesh);
        QCOMPARE(frame.tangentAgrees, frame.corners);
        QCOMPARE(frame.bitangentAgrees, frame.corners);
        QString why;
        QVERIFY2(isClosed(mesh, &why), qPrintable(why));
        QCOMPARE(uvProjectionFromName(uvProjectionName(UvProjection::Spherical)), UvProjection::Spherical);
        QCOMPARE(uvProjectionFromName(uvProjectionName(UvProjection::Box)), UvProjection::Box);
        QVERIFY(!uvProjectionFromName("planar"));
    }
};

QTEST_GUILESS_MAIN(MeshTest)
#include "MeshTest.moc"
