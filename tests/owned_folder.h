#pragma once
// A folder a test or a fuzz target owns: made with the object and removed
// with it (also when an assertion ends the test early), so that a passing
// run leaves nothing in the temp folder. Free of GoogleTest, for the fuzz
// targets too.
#include <stdlib.h>  // mkdtemp

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>

namespace stochtex::test {

class OwnedFolder {
public:
    // The folder at path, made if it is missing.
    explicit OwnedFolder(std::filesystem::path path) : path_(std::move(path)) {
        std::filesystem::create_directories(path_);
    }
    ~OwnedFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    OwnedFolder(const OwnedFolder&) = delete;
    OwnedFolder& operator=(const OwnedFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

    // A new folder <temp>/<prefix>-XXXXXX that no other process has.
    static std::filesystem::path fresh(const std::string& prefix) {
        std::string d = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
        if (!mkdtemp(d.data())) std::abort();
        return d;
    }

private:
    std::filesystem::path path_;
};

}  // namespace stochtex::test
