#pragma once
// What the workbench has open: a pattern (a preset, a pattern file or a
// texture graph, held as its JSON so that every edit is an edit of the file
// a user would write, and saving writes it back) or a ShaderToy program (a
// folder or manifest). Files on disk are watched for live reload.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/gpu/shadertoy_spec.h"
#include "stochtex/pattern/pattern_spec.h"

namespace stochtex {

class WorkbenchDocument {
public:
    enum class Kind { Pattern, Shadertoy };

    // An embedded preset (InputError for an unknown name).
    static WorkbenchDocument preset(const std::string& name);
    // A pattern or graph file; InputError naming the file if it does not parse.
    static WorkbenchDocument patternFile(const std::string& path);
    // A ShaderToy program folder or manifest (loadShadertoy's checks).
    static WorkbenchDocument shadertoy(const std::string& path);

    Kind kind() const { return kind_; }
    // "preset NAME" or the path: how messages and the title name it.
    const std::string& source() const { return source_; }
    // A pattern's JSON (Kind::Pattern).
    const nlohmann::json& json() const { return json_; }
    const std::filesystem::path& baseDir() const { return baseDir_; }
    // The pattern as parsed when its JSON last changed: each accepted change
    // is parsed once, to check it, and that parse is kept (a change that does
    // not parse is refused: InputError naming the source and the JSON
    // pointer of a bad value, as for a file).
    const PatternSpec& patternSpec() const;
    // Counts the changes of the pattern accepted (edits, undo, redo,
    // replace, reload; an edit to an equal value counts too): a value built
    // from patternSpec() at one revision is stale at another.
    uint64_t revision() const { return revision_; }
    // The program (Kind::Shadertoy), as loaded last.
    const ShadertoySpec& shadertoySpec() const { return shadertoy_; }

    // Replaces the value at a JSON pointer of the pattern (its parent must
    // exist; an array index may be one past the end, to append). The edit is
    // kept only if the pattern still parses: otherwise InputError as
    // patternSpec() words it, and the document is unchanged.
    void set(const std::string& pointer, const nlohmann::json& value);
    // Removes an array element or object member (same rule).
    void remove(const std::string& pointer);
    // Replaces the whole pattern (same rule).
    void replace(const nlohmann::json& pattern);
    // Edits since loading (or the last save).
    bool edited() const { return edited_; }

    // Undo history of a pattern. checkpoint() says that the next change
    // accepted (set, remove, replace) starts a new undo step: the pattern as
    // it was before it is kept, and what was undone is forgotten. Changes
    // without a checkpoint between them are one step (the workbench marks
    // one per gesture, so a slider dragged over many frames is one step); a
    // refused change touches nothing. undo() and redo() move between the
    // steps, skipping states equal to the current pattern, and say whether
    // they moved; the next change after them starts a new step. A state
    // that no longer parses (an image it names is gone) is refused as set()
    // refuses an edit. At most kUndoDepth states are kept.
    static constexpr size_t kUndoDepth = 256;
    void checkpoint();
    bool undo();
    bool redo();
    bool canUndo() const;
    bool canRedo() const;

    // Writes the pattern as JSON (atomically), laid out as it was read
    // (layoutLike: key order, spacing and line breaks kept where the values
    // did not change); a file's relative paths stay
    // valid only beside the file, so paths are written absolute when the
    // target is in another folder. Clears edited() when it is the source file.
    void save(const std::string& path);

    // The files the document was read from (the pattern file and the images
    // it names; a program's manifest, passes, Common and channel images),
    // watched for reload.
    const std::vector<std::filesystem::path>& watchedFiles() const { return watched_; }
    // Whether a watched file changed on disk since the last call (or load).
    bool changedOnDisk();
    // Reads the document again from disk (edits are dropped, and undo comes
    // back to them). InputError as when it was opened; the document is
    // unchanged then.
    void reload();

private:
    WorkbenchDocument() = default;
    void watch(std::vector<std::filesystem::path> files);
    Kind kind_ = Kind::Pattern;
    std::string source_, presetName_;
    std::filesystem::path path_, baseDir_;
    nlohmann::json json_;
    PatternSpec spec_;  // json_ parsed (Kind::Pattern)
    uint64_t revision_ = 0;
    PatternSpec parse(const nlohmann::json& pattern) const;
    std::string text_;  // the pattern's text as read (or last saved to its file): how saving lays it out
    ShadertoySpec shadertoy_;
    bool edited_ = false;
    std::vector<nlohmann::json> undo_, redo_;
    bool stepPending_ = true;  // the next accepted change starts an undo step
    // The change itself: kept only if the pattern still parses; `record`: into the undo history.
    void commit(nlohmann::json next, bool record);
    // A state to come back to, on top of the undo history (unless equal to the top; at most kUndoDepth).
    void remember(nlohmann::json state);
    // Moves to the nearest state of `from` unlike the current one, the current one going on `to`.
    bool travel(std::vector<nlohmann::json>& from, std::vector<nlohmann::json>& to);
    std::vector<std::filesystem::path> watched_;
    std::vector<std::filesystem::file_time_type> stamps_;
};

}  // namespace stochtex
