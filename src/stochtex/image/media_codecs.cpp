#include "stochtex/image/media_codecs.h"

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace stochtex {
namespace fs = std::filesystem;

namespace {

// The file this code was linked into: the executable, or a shared object
// (a Python module) that holds the library.
fs::path holderFile() {
    Dl_info info{};
    link_map* map = nullptr;
    if (dladdr1(reinterpret_cast<const void*>(&mediaCodecs), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) &&
        map && map->l_name && map->l_name[0] != '\0')
        return map->l_name;
    // The main program's link map has no name.
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec)
        throw std::runtime_error("cannot find the running program's file to load " + std::string(kMediaPluginFile) +
                                 " beside it (" + ec.message() + ")");
    return exe;
}

const MediaCodecs& load() {
    const fs::path plugin = holderFile().parent_path() / kMediaPluginFile;
    // OpenCV refuses EXR unless this is set before its first EXR call (in
    // the plugin); set here, once, before any of its threads can run.
    setenv("OPENCV_IO_ENABLE_OPENEXR", "1", 0);
    // Never closed: its codecs serve until the process ends.
    void* handle = dlopen(plugin.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        std::string why = dlerror();  // "<file>: <reason>"
        if (why.starts_with(plugin.string() + ": ")) why.erase(0, plugin.string().size() + 2);
        throw std::runtime_error("cannot load the media codecs (EXR, JPEG, TIFF, video) from " + plugin.string() +
                                 ": " + why);
    }
    const auto entry = reinterpret_cast<MediaPluginEntry>(dlsym(handle, kMediaPluginEntry));
    if (!entry) throw std::runtime_error(plugin.string() + " is not stochtex's media plugin: " + dlerror());
    const MediaCodecs* codecs = entry(kMediaCodecsVersion);
    if (!codecs)
        throw std::runtime_error(plugin.string() +
                                 " was built from another version of stochtex (rebuild it with the binary)");
    return *codecs;
}

}  // namespace

const MediaCodecs& mediaCodecs() {
    static const MediaCodecs& codecs = load();  // a failed load throws, and the next call tries again
    return codecs;
}

}  // namespace stochtex
