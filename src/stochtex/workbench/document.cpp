#include "stochtex/workbench/document.h"

#include <algorithm>
#include <system_error>
#include <utility>

#include "stochtex/core/atomic_file.h"
#include "stochtex/core/error.h"
#include "stochtex/pattern/json_reader.h"
#include "stochtex/pattern/pattern_parts.h"
#include "stochtex/pattern/presets.h"
#include "stochtex/workbench/json_layout.h"

namespace stochtex {

namespace fs = std::filesystem;

namespace {

// A missing file counts as changed once it is back (an editor saving by
// rename removes it for a moment).
fs::file_time_type stampOf(const fs::path& p) {
    std::error_code ec;
    const auto t = fs::last_write_time(p, ec);
    return ec ? fs::file_time_type::min() : t;
}

// Calls f on every "path" member (a string) of a pattern: its image files
// (exemplars, colormaps, profiles, graph sources), relative to the
// pattern file's folder unless absolute.
template <class Json, class F>
void forEachPath(Json& j, F&& f) {
    if (j.is_object()) {
        for (auto& [key, value] : j.items())
            if (key == "path" && value.is_string())
                f(value);
            else
                forEachPath(value, f);
    } else if (j.is_array()) {
        for (auto& value : j) forEachPath(value, f);
    }
}

}  // namespace

WorkbenchDocument WorkbenchDocument::preset(const std::string& name) {
    WorkbenchDocument d;
    d.source_ = "preset " + name;
    d.presetName_ = name;
    d.text_ = presetText(name);
    d.json_ = JsonReader::parse(d.text_, d.source_);
    d.baseDir_ = ".";
    d.spec_ = d.parse(d.json_);  // a preset always parses; checked all the same
    return d;
}

WorkbenchDocument WorkbenchDocument::patternFile(const std::string& path) {
    WorkbenchDocument d;
    d.source_ = path;
    d.path_ = path;
    d.text_ = readJsonText(path);
    d.json_ = JsonReader::parse(d.text_, path);
    d.baseDir_ = fs::path(path).parent_path();
    if (d.baseDir_.empty()) d.baseDir_ = ".";
    d.spec_ = d.parse(d.json_);
    std::vector<fs::path> files{path};
    forEachPath(d.json_,
                [&](const nlohmann::json& p) { files.push_back(d.baseDir_ / fs::path(p.get<std::string>())); });
    d.watch(std::move(files));
    return d;
}

WorkbenchDocument WorkbenchDocument::shadertoy(const std::string& path) {
    WorkbenchDocument d;
    d.kind_ = Kind::Shadertoy;
    d.source_ = path;
    d.path_ = path;
    d.shadertoy_ = loadShadertoy(path);
    std::vector<fs::path> files;
    if (!fs::is_directory(path)) files.push_back(path);  // the manifest
    // A pass embedded in a ShaderToy export lives in the export, watched above.
    if (!d.shadertoy_.common.empty() && d.shadertoy_.commonSource.empty()) files.push_back(d.shadertoy_.common);
    for (const ShadertoyPass& pass : d.shadertoy_.passes) {
        if (pass.source.empty()) files.push_back(pass.code);
        for (const ShadertoyChannel& c : pass.channels) {
            if (!c.image.empty()) files.push_back(c.image);  // an image's, a video's, an equirectangular cubemap's
            for (const auto& face : c.faces) files.push_back(face);
        }
    }
    d.watch(std::move(files));
    return d;
}

const PatternSpec& WorkbenchDocument::patternSpec() const {
    if (kind_ != Kind::Pattern) throw std::logic_error("WorkbenchDocument::patternSpec: not a pattern");
    return spec_;
}

PatternSpec WorkbenchDocument::parse(const nlohmann::json& pattern) const {
    return parsePatternSpec(JsonReader(pattern, source_), baseDir_);
}

void WorkbenchDocument::replace(const nlohmann::json& pattern) { commit(pattern, true); }

void WorkbenchDocument::commit(nlohmann::json next, bool record) {
    if (kind_ != Kind::Pattern) throw std::logic_error("WorkbenchDocument: a ShaderToy program is edited in its files");
    spec_ = parse(next);  // throws, and nothing changed, when it does not parse
    nlohmann::json before = std::exchange(json_, std::move(next));
    ++revision_;
    edited_ = true;
    if (record && stepPending_) {
        remember(std::move(before));
        redo_.clear();
        stepPending_ = false;
    }
}

void WorkbenchDocument::set(const std::string& pointer, const nlohmann::json& value) {
    nlohmann::json next = json_;
    try {
        const nlohmann::json::json_pointer p(pointer);
        if (!p.empty() && !next.contains(p.parent_pointer()))
            throw InputError(source_ + ": " + pointer + ": no such place in the pattern");
        // An index past an array's end would fill the gap with nulls
        // (".../shapes/400000000" took 14 GB): an element is replaced, or
        // appended at the end ("-" or the array's size).
        if (!p.empty()) {
            const nlohmann::json& parent = next[p.parent_pointer()];
            if (parent.is_array() && p.back() != "-" && !next.contains(p) && p.back() != std::to_string(parent.size()))
                throw InputError(source_ + ": " + pointer + ": the array holds " + std::to_string(parent.size()) +
                                 " elements; set one of them, or append at " + std::to_string(parent.size()) +
                                 " (or -)");
        }
        next[p] = value;
    } catch (const nlohmann::json::exception& e) {
        throw InputError(source_ + ": " + pointer + ": not a place in the pattern (" + e.what() + ")");
    }
    replace(next);
}

void WorkbenchDocument::remove(const std::string& pointer) {
    nlohmann::json next = json_;
    try {
        const nlohmann::json::json_pointer p(pointer);
        if (p.empty() || !next.contains(p)) throw InputError(source_ + ": " + pointer + ": nothing there to remove");
        nlohmann::json& parent = next[p.parent_pointer()];
        if (parent.is_array())
            parent.erase(size_t(std::stoul(p.back())));
        else
            parent.erase(p.back());
    } catch (const nlohmann::json::exception& e) {
        throw InputError(source_ + ": " + pointer + ": not a place in the pattern (" + e.what() + ")");
    }
    replace(next);
}

void WorkbenchDocument::save(const std::string& path) {
    if (kind_ != Kind::Pattern) throw std::logic_error("WorkbenchDocument::save: a ShaderToy program is its files");
    nlohmann::json out = json_;
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) folder = ".";
    std::error_code ec;
    if (!fs::equivalent(folder, baseDir_, ec))
        forEachPath(out, [&](nlohmann::json& value) {
            const fs::path p = value.get<std::string>();
            if (p.is_relative()) value = fs::absolute(baseDir_ / p).lexically_normal().string();
        });
    // Laid out as the file was, so that an edit's diff is the edit alone.
    const std::string text = text_.empty() ? out.dump(2) + "\n" : layoutLike(out, text_);
    writeFileAtomic(path, text);
    if (!path_.empty() && fs::equivalent(path, path_, ec)) {
        text_ = text;
        edited_ = false;
        watch(watched_);  // our own write is not a change on disk
    }
}

void WorkbenchDocument::watch(std::vector<fs::path> files) {
    watched_ = std::move(files);
    stamps_.clear();
    for (const fs::path& f : watched_) stamps_.push_back(stampOf(f));
}

bool WorkbenchDocument::changedOnDisk() {
    bool changed = false;
    for (size_t i = 0; i < watched_.size(); ++i) {
        const auto t = stampOf(watched_[i]);
        if (t != stamps_[i]) {
            stamps_[i] = t;
            changed = true;
        }
    }
    return changed;
}

void WorkbenchDocument::reload() {
    WorkbenchDocument next = kind_ == Kind::Shadertoy ? shadertoy(path_.string())
                             : path_.empty()          ? preset(presetName_)
                                                      : patternFile(path_.string());
    if (kind_ == Kind::Pattern) {
        // What was on screen stays one undo away.
        next.undo_ = std::move(undo_);
        next.remember(json_);
    }
    next.revision_ = revision_ + 1;
    *this = std::move(next);
}

void WorkbenchDocument::checkpoint() { stepPending_ = true; }

void WorkbenchDocument::remember(nlohmann::json state) {
    if (undo_.empty() || undo_.back() != state) undo_.push_back(std::move(state));
    if (undo_.size() > kUndoDepth) undo_.erase(undo_.begin());
}

bool WorkbenchDocument::travel(std::vector<nlohmann::json>& from, std::vector<nlohmann::json>& to) {
    if (kind_ != Kind::Pattern) return false;
    stepPending_ = true;  // the next change after an undo or redo is a step of its own
    while (!from.empty() && from.back() == json_) from.pop_back();
    if (from.empty()) return false;
    nlohmann::json current = json_;
    nlohmann::json state = std::move(from.back());
    from.pop_back();
    try {
        commit(state, false);
    } catch (...) {
        from.push_back(std::move(state));  // kept: the file it needs may come back
        throw;
    }
    to.push_back(std::move(current));
    return true;
}

bool WorkbenchDocument::undo() { return travel(undo_, redo_); }
bool WorkbenchDocument::redo() { return travel(redo_, undo_); }

bool WorkbenchDocument::canUndo() const {
    return std::any_of(undo_.begin(), undo_.end(), [this](const nlohmann::json& j) { return j != json_; });
}

bool WorkbenchDocument::canRedo() const {
    return std::any_of(redo_.begin(), redo_.end(), [this](const nlohmann::json& j) { return j != json_; });
}

}  // namespace stochtex
