#pragma once
// 64-bit FNV-1a (Fowler, Noll, Vo; http://www.isthe.com/chongo/tech/comp/fnv/): the one hash of
// Facet's keys and checksums (environment content hashes, IBL settings and disk-cache keys, the
// disk cache's payload checksum, the environment index's file names, mesh keys). Numbers are fed
// byte by byte in little-endian order, so a value does not depend on the machine's byte order;
// values are stored on disk, so the algorithm never changes here (a key's layout changes with a
// version in what is hashed, e.g. IblSettings' kAlgorithmVersion).
//
//   const std::uint64_t key = Fnv1a64().addUint32(width).addString(name).value();

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace facet {

class Fnv1a64 {
public:
    static constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ULL;
    static constexpr std::uint64_t kPrime = 0x100000001b3ULL;

    constexpr Fnv1a64() = default;
    // Continues from `state` (a value() of an earlier hash, or a seed).
    constexpr explicit Fnv1a64(std::uint64_t state)
        : m_state(state)
    {
    }

    constexpr Fnv1a64& addByte(std::uint8_t byte)
    {
        m_state ^= byte;
        m_state *= kPrime;
        return *this;
    }
    Fnv1a64& addBytes(const void* data, std::size_t size)
    {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
            addByte(bytes[i]);
        return *this;
    }
    constexpr Fnv1a64& addString(std::string_view text)
    {
        for (const char c : text)
            addByte(static_cast<unsigned char>(c));
        return *this;
    }
    constexpr Fnv1a64& addUint32(std::uint32_t value)
    {
        for (int i = 0; i < 4; ++i)
            addByte(std::uint8_t(value >> (8 * i)));
        return *this;
    }
    constexpr std::uint64_t value() const { return m_state; }

private:
    std::uint64_t m_state = kOffsetBasis;
};

} // namespace facet
