#include "core/image/ImageReader.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <vector>

#include <sys/stat.h>

#include "core/gltf/GltfImport.h"
#include "core/image/BuiltinExrDecoder.h"
#include "core/support/AsciiText.h"
#include "core/support/FileCheck.h"

namespace facet {

namespace {

// OIIO's messages can span several lines (libpng stacks its own under OIIO's); a message for
// the user is one line.
std::string oneLine(std::string message)
{
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
    std::string result;
    result.reserve(message.size());
    for (char c : message) {
        if (c == '\n')
            result += "; ";
        else
            result += c;
    }
    return result.empty() ? std::string("unknown error") : result;
}

// ".png", ".jpg", ".webp", ... for encoded bytes, by their signature (the MIME type a glTF asset
// gives is optional and sometimes wrong).
std::string extensionForEncodedImage(const std::vector<unsigned char>& bytes, const std::string& mimeType)
{
    const auto startsWith = [&bytes](std::initializer_list<unsigned char> signature, std::size_t at = 0) {
        if (bytes.size() < at + signature.size())
            return false;
        return std::equal(signature.begin(), signature.end(), bytes.begin() + std::ptrdiff_t(at));
    };
    if (startsWith({0x89, 'P', 'N', 'G'}))
        return ".png";
    if (startsWith({0xFF, 0xD8, 0xFF}))
        return ".jpg";
    if (startsWith({'R', 'I', 'F', 'F'}) && startsWith({'W', 'E', 'B', 'P'}, 8))
        return ".webp";
    if (startsWith({0x76, 0x2F, 0x31, 0x01}))
        return ".exr";
    if (mimeType == "image/jpeg")
        return ".jpg";
    if (mimeType == "image/webp")
        return ".webp";
    return ".png";
}

} // namespace

void setImageError(
    std::string* error, const char* function, const std::string& path, const std::string& problem)
{
    if (error)
        *error = std::string(function) + ": " + path + ": " + oneLine(problem);
}

void setImageErrorFromException(
    std::string* error, const char* function, const std::string& path, const char* doing)
{
    setImageError(error, function, path, codecExceptionMessage(std::current_exception(), doing));
}

ImageReader::~ImageReader() = default;

namespace {

constexpr double kMaxPixelsPerByte = 16384.0;

// No codec packs more than a few thousand pixels into a byte (deflate's best is about 1032:1 on
// bytes, 8 one-bit pixels each): a header claiming more than kMaxPixelsPerByte times the file's
// size belongs to a cut-short or crafted file, and reading it would allocate for the claim first
// (a 95-byte PNG claiming 32768x8192 took 4 GiB and half a minute to fail). "" when the claim fits
// or the size is unknown (bytes <= 0).
std::string pixelClaimProblem(long long width, long long height, long long bytes)
{
    if (bytes <= 0 || double(width) * double(height) <= double(bytes) * kMaxPixelsPerByte)
        return {};
    return "its header claims " + std::to_string(width) + "x" + std::to_string(height)
        + " pixels, too large for a file of " + std::to_string(bytes) + " bytes (cut short or damaged)";
}

// A little-endian 32-bit value (EXR headers).
std::uint32_t littleEndian32(const unsigned char* bytes)
{
    return std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 | std::uint32_t(bytes[2]) << 16
        | std::uint32_t(bytes[3]) << 24;
}

long long fileSizeOf(const std::string& path)
{
    struct stat info { };
    return ::stat(path.c_str(), &info) == 0 ? static_cast<long long>(info.st_size) : -1;
}

// OpenEXR reads a channel list ("chlist") past its declared size when its names run on: a 728-byte
// mutant whose list ran into the next attribute took 8-18 s of allocating to fail (FuzzTest, seed
// 22). Each list must hold whole entries (a name, a pixel type of 0-2, sampling of at least 1)
// ending with its terminator exactly at its size; "" when it does.
std::string exrChannelListProblem(const unsigned char* list, std::uint32_t size)
{
    const auto int32At = [&](std::uint32_t at) { return std::int32_t(littleEndian32(list + at)); };
    std::uint32_t at = 0;
    while (at < size && list[at] != 0) {
        const std::uint32_t name = at;
        while (at < size && list[at] != 0)
            ++at;
        if (at - name > 255 || at + 1 + 16 > size)
            return "a channel list entry runs past the list's " + std::to_string(size) + " bytes";
        ++at;
        const std::int32_t type = int32At(at);
        const std::int32_t xSampling = int32At(at + 8);
        const std::int32_t ySampling = int32At(at + 12);
        const std::string channel(reinterpret_cast<const char*>(list + name));
        if (type < 0 || type > 2)
            return "channel \"" + channel + "\" has pixel type " + std::to_string(type);
        if (xSampling < 1 || ySampling < 1)
            return "channel \"" + channel + "\" has sampling " + std::to_string(xSampling) + "x"
                + std::to_string(ySampling);
        at += 16;
    }
    if (at + 1 != size)
        return "the channel list does not end at its " + std::to_string(size) + "-byte size";
    return {};
}

// The size of an attribute of one of OpenEXR's fixed-size types, or nullopt (strings, lists,
// opaque types).
std::optional<std::uint32_t> exrFixedAttributeSize(const std::string& type)
{
    static const std::pair<const char*, std::uint32_t> kSizes[]
        = {{"box2i", 16}, {"box2f", 16}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12},
            {"v3d", 24}, {"int", 4}, {"float", 4}, {"double", 8}, {"compression", 1}, {"lineOrder", 1},
            {"envmap", 1}, {"deepImageState", 1}, {"tiledesc", 9}, {"chromaticities", 32}, {"rational", 8},
            {"keycode", 28}, {"timecode", 8}, {"m33f", 36}, {"m44f", 64}, {"m33d", 72}, {"m44d", 128}};
    for (const auto& [name, size] : kSizes)
        if (type == name)
            return size;
    return std::nullopt;
}

// OpenEXR reads a header attribute's declared size before it checks it against the file: a
// 695-byte file whose string attribute claims 2 GiB took 7-13 s (allocating and reading) to fail.
// The header is a list of (name, type, 32-bit size, value) ending with an empty name (one list
// per part in a multi-part file); a size beyond what the file holds is refused here, before
// OpenImageIO sees the file. So are the other claims OpenEXR believes as it opens a file (the
// a channel list, fixed-size attributes, the data window). "" when the file is not an EXR or its
// headers are sound.
// `head`: the file's first bytes (containerProblem's), which begin with the EXR magic number.
std::string exrHeaderProblem(const std::vector<unsigned char>& head, long long fileSize)
{
    if (head.size() < 8)
        return {};
    const bool multipart = (head[5] & 0x10) != 0; // version flags, bit 12
    std::size_t at = 8;
    const auto readName = [&](std::string* out) {
        out->clear();
        while (at < head.size() && head[at] != 0 && out->size() < 256)
            out->push_back(char(head[at++]));
        if (at >= head.size() || head[at] != 0)
            return false;
        ++at;
        return true;
    };
    for (int part = 0; part < 1024; ++part) {
        std::string name, type;
        if (!readName(&name))
            return {}; // beyond the first MiB or cut short: OpenEXR's own message
        if (name.empty())
            return {}; // end of the header (of the headers, for a multi-part file: an empty header)
        for (;;) {
            if (!readName(&type) || at + 4 > head.size())
                return {};
            const std::uint32_t size = littleEndian32(head.data() + at);
            at += 4;
            if (size
                > std::uint64_t(std::max<long long>(fileSize, 0)) - std::min<std::uint64_t>(at, fileSize))
                return "broken EXR header: attribute \"" + name + "\" (" + type + ") claims "
                    + std::to_string(size) + " bytes, more than the " + std::to_string(fileSize)
                    + "-byte file holds";
            // OpenEXR reads an attribute of a fixed-size type as that many bytes whatever size
            // the header declares: a box2i declared 15 bytes long shifted every attribute after it,
            // and the next "size" read was 1.8 GB (a FuzzTest mutant).
            if (const std::optional<std::uint32_t> fixed = exrFixedAttributeSize(type);
                fixed && size != *fixed)
                return "broken EXR header: attribute \"" + name + "\" (" + type + ") is "
                    + std::to_string(size) + " bytes, not " + std::to_string(*fixed);
            if (type == "chlist" && at + size <= head.size())
                if (const std::string problem = exrChannelListProblem(head.data() + at, size);
                    !problem.empty())
                    return "broken EXR header: attribute \"" + name + "\": " + problem;
            // OpenEXR sizes its line buffers and offset table from the data window as it opens the
            // file: a 695-byte mutant claiming 16777232 x 8 pixels allocated gigabytes first (16 s
            // under AddressSanitizer). The checks Image and MapImage make after opening, made before.
            if (name == "dataWindow" && type == "box2i" && size == 16 && at + size <= head.size()) {
                std::int64_t box[4];
                for (int i = 0; i < 4; ++i)
                    box[i] = std::int32_t(littleEndian32(head.data() + at + 4 * std::size_t(i)));
                const std::int64_t width = box[2] - box[0] + 1;
                const std::int64_t height = box[3] - box[1] + 1;
                const std::string claim = std::to_string(width) + "x" + std::to_string(height);
                if (width <= 0 || height <= 0)
                    return "invalid size " + claim;
                if (width > Image::kMaxDimension || height > Image::kMaxDimension)
                    return "image too large: " + claim + " exceeds the limit of "
                        + std::to_string(Image::kMaxDimension) + " pixels per side";
                if (std::string problem = pixelClaimProblem(width, height, fileSize); !problem.empty())
                    return problem;
            }
            at += size;
            if (!readName(&name))
                return {};
            if (name.empty())
                break;
        }
        if (!multipart)
            return {};
    }
    return {};
}

// libpng, like OpenEXR, believes a chunk's length before the file: a 422-byte PNG whose tEXt
// chunk claims 4 GiB took 5-11 s to fail. The chunks (32-bit big-endian length, type, data, CRC)
// are walked by their headers alone (a few reads for a real file), and one longer than the rest
// of the file is refused. "" when the file is not a PNG or its chunks fit.
// `file`: open on a file that begins with the PNG signature (chunks beyond containerProblem's head
// are reached by seeking).
std::string pngChunkProblem(std::FILE* file, long long fileSize)
{
    std::string problem;
    {
        long long at = 8;
        for (int chunk = 0; chunk < (1 << 20) && at + 12 <= fileSize; ++chunk) {
            unsigned char head[8];
            if (std::fseek(file, long(at), SEEK_SET) != 0 || std::fread(head, 1, 8, file) != 8)
                break;
            const long long length = (long long)head[0] << 24 | (long long)head[1] << 16
                | (long long)head[2] << 8 | (long long)head[3];
            const std::string type(reinterpret_cast<const char*>(head + 4), 4);
            if (length > fileSize - at - 12) {
                problem = "broken PNG: chunk \"" + type + "\" claims " + std::to_string(length)
                    + " bytes, more than the " + std::to_string(fileSize) + "-byte file holds";
                break;
            }
            if (type == "IEND")
                break;
            at += 12 + length;
        }
    }
    return problem;
}

// OpenImageIO 2.4 copies a JPEG's IPTC records (APP13, "Photoshop 3.0", resource 0x0404) by the
// lengths they claim without checking them against the segment: a segment cut short read past its
// buffer (AddressSanitizer: heap-buffer-overflow in decode_iptc_iim, found by FuzzTest). The APP13
// segments are walked here, resource by resource and record by record, and one that claims more
// than its segment holds is refused. "" when the file is not a JPEG or its IPTC data is sound.
// `bytes`: the file's first bytes (containerProblem's), which begin with a JPEG's SOI marker.
std::string jpegIptcProblem(const std::vector<unsigned char>& bytes)
{
    if (bytes.size() < 4)
        return {};
    const auto u16 = [&bytes](std::size_t at) { return std::size_t(bytes[at]) << 8 | bytes[at + 1]; };
    const auto u32 = [&bytes](std::size_t at) {
        return std::size_t(bytes[at]) << 24 | std::size_t(bytes[at + 1]) << 16
            | std::size_t(bytes[at + 2]) << 8 | bytes[at + 3];
    };
    std::size_t at = 2;
    while (at + 4 <= bytes.size() && bytes[at] == 0xff) {
        const unsigned marker = bytes[at + 1];
        if (marker == 0xda || marker == 0xd9)
            break; // image data (or the end): no metadata after it
        const std::size_t length = u16(at + 2);
        const std::size_t begin = at + 4;
        const std::size_t end = std::min(at + 2 + length, bytes.size());
        static const char kPhotoshop[] = "Photoshop 3.0";
        if (marker == 0xed && end >= begin + sizeof kPhotoshop
            && std::memcmp(&bytes[begin], kPhotoshop, sizeof kPhotoshop) == 0) {
            std::size_t r = begin + sizeof kPhotoshop;
            while (r + 12 <= end && std::memcmp(&bytes[r], "8BIM", 4) == 0) {
                const std::size_t id = u16(r + 4);
                std::size_t nameLength = bytes[r + 6] + 1;
                nameLength += nameLength % 2;
                const std::size_t sizeAt = r + 6 + nameLength;
                if (sizeAt + 4 > end)
                    return "broken JPEG metadata: a Photoshop resource is cut short by its APP13 segment";
                const std::size_t size = u32(sizeAt);
                const std::size_t data = sizeAt + 4;
                if (size > end - data)
                    return "broken JPEG metadata: Photoshop resource " + std::to_string(id) + " claims "
                        + std::to_string(size) + " bytes, more than its APP13 segment holds";
                if (id == 0x0404) {
                    for (std::size_t i = data; i + 5 <= data + size && bytes[i] == 0x1c;) {
                        const std::size_t recordLength = u16(i + 3);
                        if ((recordLength & 0x8000) || recordLength > data + size - (i + 5))
                            return "broken JPEG metadata: an IPTC record claims "
                                + std::to_string(recordLength) + " bytes, more than its segment holds";
                        i += 5 + recordLength;
                    }
                }
                r = data + size + size % 2;
            }
        }
        at += 2 + length;
    }
    return {};
}

// A JPEG cut short: libjpeg warns "Premature end of JPEG file" and fills the rest of the image
// with grey, and OpenImageIO 2.4 passes that on as a success (issue 29: a truncated JPEG loaded
// half grey without a word). A whole JPEG ends its image data with the EOI marker (FF D9), which
// the entropy-coded data cannot hold (an FF there is followed by 00 or a restart marker), so a
// file without one after its first scan (SOS, FF DA) is cut short. Trailing bytes after EOI (some
// cameras append data) are allowed. `head`: the file's first bytes (from the SOI marker on).
std::string jpegTruncationProblem(std::FILE* file, const std::vector<unsigned char>& head, long long fileSize)
{
    // Walk the marker segments to the first scan (APP1's EXIF thumbnail, with its own EOI, is
    // skipped whole).
    std::size_t at = 2;
    long long scan = -1;
    while (at + 4 <= head.size() && head[at] == 0xff) {
        const unsigned marker = head[at + 1];
        if (marker == 0xff) { // fill byte
            ++at;
            continue;
        }
        if (marker == 0xda) {
            scan = static_cast<long long>(at);
            break;
        }
        if (marker == 0xd9)
            return {}; // EOI before any scan: OpenImageIO says what is wrong
        at += 2 + (std::size_t(head[at + 2]) << 8 | head[at + 3]);
    }
    if (scan < 0)
        return {}; // no scan in the first MiB: not for this check to judge
    // Most files end with EOI: look at the end first, then search the whole scan data.
    unsigned char tail[2] = {0, 0};
    if (fileSize >= 2 && std::fseek(file, long(fileSize - 2), SEEK_SET) == 0
        && std::fread(tail, 1, 2, file) == 2 && tail[0] == 0xff && tail[1] == 0xd9)
        return {};
    if (std::fseek(file, long(scan), SEEK_SET) != 0)
        return {};
    std::vector<unsigned char> chunk(1 << 16);
    bool lastWasFf = false;
    for (std::size_t got; (got = std::fread(chunk.data(), 1, chunk.size(), file)) > 0;)
        for (std::size_t i = 0; i < got; ++i) {
            if (lastWasFf && chunk[i] == 0xd9)
                return {};
            lastWasFf = chunk[i] == 0xff;
        }
    return "broken JPEG: the image data ends without its end marker (the file is cut short; "
           "its lower part would be grey)";
}

// A TIFF cut short: OpenImageIO 2.4 reads the strips or tiles that are there and leaves the rest
// black, reporting success (issue 29). The first image's strip (or tile) offsets and byte counts
// (tags 273/279, 324/325) are read from its directory, and one that ends past the end of the file
// is refused. Classic TIFF only (BigTIFF is left to the reader). "" when sound or not judged.
std::string tiffTruncationProblem(std::FILE* file, const std::vector<unsigned char>& head, long long fileSize)
{
    if (head.size() < 8)
        return {};
    const bool little = head[0] == 'I';
    const auto read = [&](long long offset, std::size_t bytes, unsigned char* out) {
        return offset >= 0 && offset + static_cast<long long>(bytes) <= fileSize
            && std::fseek(file, long(offset), SEEK_SET) == 0 && std::fread(out, 1, bytes, file) == bytes;
    };
    const auto value = [little](const unsigned char* b, int bytes) {
        std::uint64_t v = 0;
        for (int i = 0; i < bytes; ++i)
            v |= std::uint64_t(b[i]) << (8 * (little ? i : bytes - 1 - i));
        return v;
    };
    if (value(&head[2], 2) != 42)
        return {}; // BigTIFF (43) or not TIFF
    const long long ifd = static_cast<long long>(value(&head[4], 4));
    unsigned char countBytes[2];
    if (!read(ifd, 2, countBytes))
        return {};
    const std::uint64_t entries = value(countBytes, 2);
    // A strip (or tile) array: its values' size, count and where they are.
    struct Field {
        int size = 0;
        std::uint64_t count = 0;
        long long at = -1;
    };
    Field offsets, counts;
    for (std::uint64_t e = 0; e < entries; ++e) {
        unsigned char entry[12];
        if (!read(ifd + 2 + static_cast<long long>(e) * 12, 12, entry))
            return {};
        const std::uint64_t tag = value(entry, 2);
        const std::uint64_t type = value(entry + 2, 2);
        const int size = type == 3 ? 2 : type == 4 ? 4 : 0; // SHORT or LONG
        if (size == 0)
            continue;
        Field field {size, value(entry + 4, 4), -1};
        field.at = field.count * std::uint64_t(size) <= 4 ? ifd + 2 + static_cast<long long>(e) * 12 + 8
                                                          : static_cast<long long>(value(entry + 8, 4));
        if (tag == 273 || tag == 324)
            offsets = field;
        else if (tag == 279 || tag == 325)
            counts = field;
    }
    if (offsets.at < 0 || counts.at < 0 || offsets.count != counts.count || offsets.count == 0
        || offsets.count > (1u << 24))
        return {};
    std::vector<unsigned char> a(offsets.count * std::size_t(offsets.size));
    std::vector<unsigned char> b(counts.count * std::size_t(counts.size));
    if (!read(offsets.at, a.size(), a.data()) || !read(counts.at, b.size(), b.data()))
        return {}; // the reader reports a directory past the end itself
    for (std::uint64_t i = 0; i < offsets.count; ++i) {
        const std::uint64_t start = value(&a[i * std::size_t(offsets.size)], offsets.size);
        const std::uint64_t length = value(&b[i * std::size_t(counts.size)], counts.size);
        if (start + length > std::uint64_t(fileSize))
            return "broken TIFF: its image data ends at byte " + std::to_string(start + length)
                + ", past the end of the " + std::to_string(fileSize)
                + "-byte file (it is cut short; the missing part would be black)";
    }
    return {};
}

// Container headers whose sizes OpenImageIO's readers believe before the file's (above): the
// file's first MiB is read once and the check of its format, told by its signature, runs on it.
// "" for a sound file, a file of another format, or one that cannot be opened (OpenImageIO's
// own message then says why). *exr: the signature is OpenEXR's.
std::string containerProblem(const std::string& path, long long fileSize, bool* exr)
{
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file)
        return {};
    // EXR headers and JPEG metadata segments are small: 1 MiB covers any real one.
    std::vector<unsigned char> head(
        std::size_t(std::min<long long>(std::max<long long>(fileSize, 0), 1 << 20)));
    head.resize(std::fread(head.data(), 1, head.size(), file));
    static const unsigned char kExr[4] = {0x76, 0x2f, 0x31, 0x01};
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::string problem;
    *exr = head.size() >= 4 && std::memcmp(head.data(), kExr, 4) == 0;
    if (*exr)
        problem = exrHeaderProblem(head, fileSize);
    else if (head.size() >= 8 && std::memcmp(head.data(), kPng, 8) == 0)
        problem = pngChunkProblem(file, fileSize);
    else if (head.size() >= 2 && head[0] == 0xff && head[1] == 0xd8) {
        problem = jpegIptcProblem(head);
        if (problem.empty())
            problem = jpegTruncationProblem(file, head, fileSize);
    } else if (head.size() >= 4 && ((head[0] == 'I' && head[1] == 'I') || (head[0] == 'M' && head[1] == 'M')))
        problem = tiffTruncationProblem(file, head, fileSize);
    std::fclose(file);
    return problem;
}

} // namespace

std::optional<ImageReader> ImageReader::open(
    const std::string& path, const char* function, std::string* error)
{
    ImageReader reader;
    reader.m_path = path;
    // An image embedded in a glTF asset ("asset.glb#images/2", core/gltf/GltfImport.h) is decoded
    // from memory: OpenImageIO picks the reader by the name's extension, which comes from the
    // bytes' signature.
    std::string openName = path;
    const FileCheck check = checkRegularFile(path);
    if (check.kind == FileKind::Missing) {
        const std::optional<GltfImageReference> reference = parseGltfImageReference(path);
        if (!reference) {
            setImageError(error, function, path, check.problem);
            return std::nullopt;
        }
        std::string mimeType;
        std::string problem;
        auto bytes = readGltfImage(*reference, &mimeType, &problem);
        if (!bytes) {
            if (error)
                *error = std::string(function) + ": " + problem;
            return std::nullopt;
        }
        reader.m_embedded = std::make_unique<std::vector<unsigned char>>(std::move(*bytes));
        openName = "embedded" + extensionForEncodedImage(*reader.m_embedded, mimeType);
    } else if (check.kind == FileKind::Folder) {
        setImageError(error, function, path, "is a directory, not an image");
        return std::nullopt;
    } else if (!check.ok()) {
        // A device (/dev/zero), a FIFO or a socket would be read forever or block; a symbolic
        // link loop or a path with a NUL byte is named as such.
        setImageError(error, function, path, check.problem);
        return std::nullopt;
    }
    std::string problem;
    if (!reader.m_embedded) {
        // Container headers whose sizes OpenImageIO's readers believe before the file's.
        reader.m_fileSize = fileSizeOf(path);
        bool& exr = reader.m_exr;
        if (const std::string container = containerProblem(path, reader.m_fileSize, &exr);
            !container.empty()) {
            setImageError(error, function, path, container);
            return std::nullopt;
        }
        // OpenEXR files core decodes itself (core/image/BuiltinExrDecoder.h), unless their layout is
        // one only the module reads.
        if (exr) {
            bool handled = true;
            if (ImageDecoder* decoder = openBuiltinExr(path, &handled, &problem)) {
                reader.m_decoder = std::unique_ptr<ImageDecoder, Close>(decoder, Close {&builtinExrCodec()});
                return reader;
            }
            if (handled) {
                setImageError(error, function, path, problem);
                return std::nullopt;
            }
        }
    }

    const ImageCodec* codec = imageCodec(&problem);
    if (!codec) {
        setImageError(error, function, path, problem);
        return std::nullopt;
    }
    const unsigned char* memory = reader.m_embedded ? reader.m_embedded->data() : nullptr;
    reader.m_decoder = std::unique_ptr<ImageDecoder, Close>(
        codec->open(openName, memory, reader.m_embedded ? reader.m_embedded->size() : 0, &problem),
        Close {codec});
    if (!reader.m_decoder) {
        setImageError(error, function, path, problem);
        return std::nullopt;
    }
    return reader;
}

bool ImageReader::checkHeader(const char* function, std::string* error) const
{
    const CodecHeader& header = this->header();
    if (header.width <= 0 || header.height <= 0) {
        setImageError(error, function, m_path,
            "invalid size " + std::to_string(header.width) + "x" + std::to_string(header.height));
        return false;
    }
    if (header.depth > 1) {
        setImageError(error, function, m_path,
            "volume images (depth " + std::to_string(header.depth) + ") are not supported");
        return false;
    }
    if (header.channels <= 0) {
        setImageError(error, function, m_path, "image has no channels");
        return false;
    }
    // OpenEXR's one integer type holds IDs and masks (object or material IDs), not light or
    // colour: read as a normalised number (value / 2^32) it was black without a word (issue 29).
    if (m_exr && header.sample == CodecSample::UInt32) {
        setImageError(error, function, m_path,
            "its channels are 32-bit unsigned integers (an ID or mask pass, not an image of colours or "
            "values); save it with half or float channels");
        return false;
    }
    return true;
}

bool ImageReader::checkSizeAgainstFile(const char* function, std::string* error) const
{
    const CodecHeader& header = this->header();
    const long long bytes = m_embedded ? static_cast<long long>(m_embedded->size()) : m_fileSize;
    if (const std::string problem = pixelClaimProblem(header.width, header.height, bytes); !problem.empty()) {
        setImageError(error, function, m_path, problem);
        return false;
    }
    return true;
}

bool ImageReader::read(int begin, int end, int channels, CodecSample as, void* data, std::ptrdiff_t xstride,
    std::ptrdiff_t ystride, const char* function, std::string* error)
{
    if (codec()->read(m_decoder.get(), begin, end, channels, as, data, xstride, ystride))
        return true;
    const std::string reason = codec()->lastError(m_decoder.get());
    setImageError(
        error, function, m_path, reason.empty() ? std::string("could not read the pixels") : reason);
    return false;
}

// What the numbers of a file mean. OIIO names the colour space when the format says it
// ("sRGB" for PNG/JPEG/WebP, "Linear" for EXR, "linear" for Radiance HDR, "GammaCorrected2.2"
// for a PNG with a gAMA chunk) and says nothing for TIFF or TGA. Without a name, the
// convention of the formats decides: 8/16-bit integer files are sRGB-encoded colour (PNG, JPEG,
// TGA, 8-bit TIFF as painting tools write them), float files (EXR, HDR, float TIFF) are linear.
ColorEncoding ImageReader::encoding() const
{
    const std::string name = asciiLowercase(colorSpaceName());
    // A 2.2 power curve is not the sRGB curve but close to it (within 0.4% of full scale),
    // and what a gamma-tagged PNG's author meant.
    if (name.find("srgb") != std::string::npos || name.rfind("gammacorrected", 0) == 0)
        return ColorEncoding::SRGB;
    if (name.find("linear") != std::string::npos || name.rfind("lin_", 0) == 0 || name == "acescg"
        || name == "aces2065-1" || name == "raw")
        return ColorEncoding::Linear;
    switch (header().sample) {
    case CodecSample::UInt8:
    case CodecSample::Int8:
    case CodecSample::UInt16:
    case CodecSample::Int16:
        return ColorEncoding::SRGB;
    default:
        return ColorEncoding::Linear;
    }
}

bool ImageReader::twoColourChannels() const
{
    const CodecHeader& header = this->header();
    return header.channels == 2 && header.channelNames.size() == 2 && header.channelNames[0] == "R"
        && header.channelNames[1] == "G";
}

} // namespace facet
