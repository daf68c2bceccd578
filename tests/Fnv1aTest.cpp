// core/support/Fnv1a: the one FNV-1a 64 of Facet's keys and checksums. Its values are stored on disk (IBL
// cache keys and checksums, the environment index's file names), so they are pinned here: the
// published test vectors, numbers fed little-endian whatever the machine, and a hash continued
// from a seed (AssetCache::meshKey) equal to one fed in a single run.

#include "core/support/Fnv1a.h"

#include <QtTest/QTest>

#include <cstdint>
#include <string>

using namespace facet;

class Fnv1aTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void publishedVectors_data()
    {
        // From the FNV reference (http://www.isthe.com/chongo/tech/comp/fnv/, test_fnv.c).
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<quint64>("expected");
        QTest::newRow("empty") << QByteArray() << quint64(0xcbf29ce484222325ULL);
        QTest::newRow("a") << QByteArray("a") << quint64(0xaf63dc4c8601ec8cULL);
        QTest::newRow("b") << QByteArray("b") << quint64(0xaf63df4c8601f1a5ULL);
        QTest::newRow("foobar") << QByteArray("foobar") << quint64(0x85944171f73967e8ULL);
    }
    void publishedVectors()
    {
        QFETCH(QByteArray, text);
        QFETCH(quint64, expected);
        const std::string s = text.toStdString();
        QCOMPARE(quint64(Fnv1a64().addString(s).value()), expected);
        QCOMPARE(quint64(Fnv1a64().addBytes(s.data(), s.size()).value()), expected);
        Fnv1a64 byByte;
        for (char c : s)
            byByte.addByte(static_cast<unsigned char>(c));
        QCOMPARE(quint64(byByte.value()), expected);
    }

    void numbersAreLittleEndian()
    {
        const unsigned char bytes[4] = {0x78, 0x56, 0x34, 0x12};
        QCOMPARE(Fnv1a64().addUint32(0x12345678u).value(), Fnv1a64().addBytes(bytes, 4).value());
        QVERIFY(Fnv1a64().addUint32(1u).value() != Fnv1a64().addUint32(0x01000000u).value());
    }

    void continuesFromAState()
    {
        const std::uint64_t half = Fnv1a64().addString("foo").value();
        QCOMPARE(Fnv1a64(half).addString("bar").value(), Fnv1a64().addString("foobar").value());
        // A seed other than the offset basis is another key space (AssetCache::meshKey).
        QVERIFY(Fnv1a64(1u).addString("foobar").value() != Fnv1a64().addString("foobar").value());
    }
};

QTEST_GUILESS_MAIN(Fnv1aTest)
#include "Fnv1aTest.moc"
