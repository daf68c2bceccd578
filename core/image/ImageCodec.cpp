#include "core/image/ImageCodec.h"

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <dlfcn.h>

namespace facet {

namespace {

struct LoadedCodec {
    const ImageCodec* codec = nullptr;
    std::string error;
};

std::atomic<bool> g_loaded {false};

LoadedCodec load()
{
    LoadedCodec result;
    const std::string path = imageCodecModulePath();
    const auto fail = [&](const std::string& why) {
        result.error = "image input/output module " + path + ": " + why;
        return result;
    };
    // RTLD_LOCAL: OpenImageIO's symbols stay the module's. RTLD_LAZY: the functions of the ~260
    // libraries behind it are bound as they are first called, not all at load (RTLD_NOW measured
    // the same load time). A library that is missing still fails here, with the loader's message;
    // the version check below refuses a module of another build.
    void* handle = ::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
        const char* loader = ::dlerror();
        std::string why = loader ? loader : "cannot be loaded";
        if (why.starts_with(path + ": ")) // the loader names the file too
            why.erase(0, path.size() + 2);
        return fail(why);
    }
    // Never closed: the decoders and the codec it returns live as long as the process.
    using EntryPoint = const ImageCodec* (*)();
    const auto entry = reinterpret_cast<EntryPoint>(::dlsym(handle, kImageCodecEntryPoint));
    if (!entry)
        return fail(std::string("has no ") + kImageCodecEntryPoint + " (not a Facet image module)");
    const ImageCodec* codec = entry();
    if (!codec || codec->interfaceVersion != kImageCodecInterfaceVersion)
        return fail("belongs to another build of Facet (interface version "
            + std::to_string(codec ? codec->interfaceVersion : 0) + ", this build's is "
            + std::to_string(kImageCodecInterfaceVersion) + ")");
    result.codec = codec;
    g_loaded = true;
    return result;
}

const LoadedCodec& loadedCodec()
{
    static const LoadedCodec loaded = load(); // thread-safe, once
    return loaded;
}

} // namespace

std::string imageCodecModulePath()
{
    if (const char* overridden = std::getenv("FACET_IMAGEIO_MODULE"); overridden && *overridden)
        return overridden;
    std::error_code ec;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path folder = ec ? std::filesystem::path(".") : executable.parent_path();
    return (folder.parent_path() / "lib" / "facet" / "libfacet_imageio.so").string();
}

const ImageCodec* imageCodec(std::string* error)
{
    const LoadedCodec& loaded = loadedCodec();
    if (!loaded.codec && error)
        *error = loaded.error;
    return loaded.codec;
}

bool imageCodecLoaded()
{
    return g_loaded;
}

} // namespace facet
