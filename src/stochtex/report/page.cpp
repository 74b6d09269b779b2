#include "stochtex/report/page.h"

#include <filesystem>
#include <sstream>

#include "stochtex/core/error.h"
#include "stochtex/image/image_io.h"
#include "stochtex/report/table.h"

namespace stochtex {

void ensureFolder(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) throw InputError(dir + ": cannot create output folder");
}

void writeFigures(const std::string& dir, const std::vector<Figure>& figures) {
    for (const auto& f : figures) writeImage((std::filesystem::path(dir) / f.file).string(), f.image, kNoTransfer);
}

void writeText(const std::string& dir, const std::string& file, const std::string& text) {
    writeFileAtomic((std::filesystem::path(dir) / file).string(), text);
}

std::string htmlFigures(const std::string& prefix, const std::vector<Figure>& figures, size_t limit) {
    std::ostringstream h;
    size_t shown = 0;
    for (const auto& f : figures) {
        if (f.caption.empty()) continue;
        if (shown++ == limit) break;
        h << "<figure><a href='" << prefix << f.file << "'><img src='" << prefix << f.file << "'></a><figcaption>"
          << htmlEscape(f.caption) << "</figcaption></figure>\n";
    }
    return h.str();
}

std::string htmlPage(const std::string& title, const std::string& body, int maxWidthPx, int captionWidthPx) {
    std::ostringstream h;
    h << "<!doctype html><html><head><meta charset='utf-8'><title>" << htmlEscape(title)
      << "</title><style>body{font-family:sans-serif;max-width:" << maxWidthPx
      << "px;margin:2em auto;color:#222}"
         "figure{display:inline-block;margin:0 1em 1.5em 0;vertical-align:top;max-width:100%}"
         "img{max-width:100%}figcaption{max-width:"
      << captionWidthPx
      << "px;font-size:90%}table{border-collapse:collapse;margin:.5em 0 1.5em}"
         "td,th{border:1px solid #bbb;padding:.25em .6em;text-align:right}</style></head><body>"
      << body << "</body></html>\n";
    return h.str();
}

}  // namespace stochtex
