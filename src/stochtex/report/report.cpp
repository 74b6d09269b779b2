#include "stochtex/report/report.h"

#include <filesystem>

namespace stochtex {

namespace {

std::string joinFolder(const std::string& a, const std::string& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return a + "/" + b;
}

std::string prefixOf(const std::string& folder) { return folder.empty() ? "" : folder + "/"; }

}  // namespace

std::string reportPage(const Report& report) {
    std::string body = "<h1>" + htmlEscape(report.title) + "</h1>" + report.html + "\n";
    for (const ReportSection& s : report.sections) {
        if (!s.heading.empty()) body += "<h2>" + htmlEscape(s.heading) + "</h2>\n";
        body += s.html;
        for (const ReportTable& t : s.tables)
            if (t.onPage) body += t.table.html();
        body += htmlFigures(prefixOf(s.folder), s.figures, s.figuresShown) + s.htmlAfter + "\n";
    }
    return htmlPage(report.title, body, report.maxWidthPx, report.captionWidthPx);
}

std::vector<std::string> writeReport(const std::string& folder, const Report& report) {
    std::vector<std::string> written;
    for (const ReportSection& s : report.sections) {
        const std::string dir = (std::filesystem::path(folder) / s.folder).string();
        const std::string prefix = prefixOf(s.folder);
        ensureFolder(dir);
        writeFigures(dir, s.figures);
        for (const Figure& f : s.figures) written.push_back(prefix + f.file);
        for (const ReportTable& t : s.tables) {
            if (t.file.empty()) continue;
            writeText(dir, t.file, t.table.csv());
            written.push_back(prefix + t.file);
        }
        for (const ReportFile& f : s.files) {
            writeText(dir, f.file, f.text);
            written.push_back(prefix + f.file);
        }
    }
    ensureFolder(folder);
    writeText(folder, "index.html", reportPage(report));
    written.push_back("index.html");
    return written;
}

void appendReport(Report& into, Report part, const std::string& folder, const std::string& heading,
                  const std::string& html) {
    ReportSection lead;
    lead.heading = heading.empty() ? part.title : heading;
    lead.html = html + part.html;
    if (!part.sections.empty() && part.sections.front().heading.empty()) {
        ReportSection& first = part.sections.front();
        first.heading = lead.heading;
        first.html = lead.html + first.html;
    } else {
        part.sections.insert(part.sections.begin(), std::move(lead));
    }
    for (ReportSection& s : part.sections) {
        s.folder = joinFolder(folder, s.folder);
        into.sections.push_back(std::move(s));
    }
}

std::string listNames(const std::vector<std::string>& names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return out;
}

}  // namespace stochtex
