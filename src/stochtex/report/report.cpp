#include "stochtex/report/report.h"

#include <algorithm>
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

Report sectionReport(std::string title, std::vector<ReportTable> tables, std::vector<Figure> figures,
                     std::string html) {
    Report report;
    report.title = std::move(title);
    ReportSection s;
    s.html = std::move(html);
    s.tables = std::move(tables);
    s.figures = std::move(figures);
    report.sections.push_back(std::move(s));
    return report;
}

std::string reportPage(const Report& report) {
    std::string body = "<h1>" + htmlEscape(report.title) + "</h1>" + report.html + "\n";
    for (const ReportSection& s : report.sections) {
        std::string h = "h";
        h += std::to_string(std::clamp(s.level, 1, 6));
        if (!s.heading.empty()) body += "<" + h + ">" + htmlEscape(s.heading) + "</" + h + ">\n";
        body += s.html;
        for (const ReportTable& t : s.tables)
            if (t.onPage) body += t.table.html();
        for (const ReportVideo& v : s.videos) body += htmlAnimatedPreview(prefixOf(s.folder), v.name, v.caption) + "\n";
        body += htmlFigures(prefixOf(s.folder), s.figures, s.figuresShown) + s.htmlAfter + "\n";
    }
    return htmlPage(report.title, body, report.maxWidthPx, report.captionWidthPx);
}

void writeReportPage(const std::string& folder, const Report& report) {
    ensureFolder(folder);
    writeText(folder, "index.html", reportPage(report));
}

std::vector<std::string> writeReport(const std::string& folder, const Report& report) {
    std::vector<std::string> written;
    // A figure shown in two sections of one folder is written once.
    const auto firstTime = [&](const std::string& name) {
        if (std::find(written.begin(), written.end(), name) != written.end()) return false;
        written.push_back(name);
        return true;
    };
    for (const ReportSection& s : report.sections) {
        const std::string dir = (std::filesystem::path(folder) / s.folder).string();
        const std::string prefix = prefixOf(s.folder);
        ensureFolder(dir);
        for (const Figure& f : s.figures)
            if (firstTime(prefix + f.file)) writeFigure(dir, f);
        for (const ReportTable& t : s.tables)
            if (!t.file.empty() && firstTime(prefix + t.file)) writeText(dir, t.file, t.table.csv());
        for (const ReportFile& f : s.files)
            if (firstTime(prefix + f.file))
                writeText(dir, f.file, f.pageTitle.empty() ? f.text : htmlPage(f.pageTitle, f.text));
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
    for (ReportSection& s : part.sections) ++s.level;  // under the part's heading
    if (!part.sections.empty() && part.sections.front().heading.empty()) {
        ReportSection& first = part.sections.front();
        first.heading = lead.heading;
        first.level = lead.level;
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
