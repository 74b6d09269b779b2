#include "report.h"

#include <filesystem>
#include <sstream>

#include "common.h"
#include "stochtex/core/error.h"

namespace stochtex::cli {

void ensureFolder(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) throw InputError(dir + ": cannot create output folder");
}

std::string htmlFigures(const std::string& prefix, const std::vector<Figure>& figures, size_t limit) {
    std::ostringstream h;
    for (size_t i = 0; i < figures.size() && i < limit; ++i)
        h << "<figure><a href='" << prefix << figures[i].file << "'><img src='" << prefix << figures[i].file
          << "'></a><figcaption>" << htmlEscape(figures[i].caption) << "</figcaption></figure>\n";
    return h.str();
}

std::string markdownToHtml(const std::string& md) {
    std::istringstream in(md);
    std::ostringstream h;
    std::string line;
    bool inTable = false, header = false;
    while (std::getline(in, line)) {
        if (line.rfind("|---", 0) == 0) continue;
        if (!line.empty() && line[0] == '|') {
            if (!inTable) {
                h << "<table>";
                inTable = header = true;
            }
            h << "<tr>";
            std::istringstream cells(line.substr(1));
            std::string c;
            while (std::getline(cells, c, '|')) {
                const auto a = c.find_first_not_of(' '), b = c.find_last_not_of(' ');
                if (a == std::string::npos) continue;
                h << (header ? "<th>" : "<td>") << htmlEscape(c.substr(a, b - a + 1)) << (header ? "</th>" : "</td>");
            }
            h << "</tr>";
            header = false;
            continue;
        }
        if (inTable) {
            h << "</table>\n";
            inTable = false;
        }
        if (line.size() > 4 && line.rfind("**", 0) == 0) {
            const auto end = line.find("**", 2);
            h << "<p><b>" << htmlEscape(line.substr(2, end - 2)) << "</b>" << htmlEscape(line.substr(end + 2))
              << "</p>\n";
        }
    }
    if (inTable) h << "</table>\n";
    return h.str();
}

}  // namespace stochtex::cli
