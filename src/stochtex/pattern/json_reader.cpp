#include "stochtex/pattern/json_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/names.h"

namespace stochtex {

namespace {
std::string escapePointerToken(const std::string& key) {
    std::string out;
    for (char c : key) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

// A string as a message quotes it: at most 40 characters.
std::string quoteShort(const std::string& s) { return "\"" + (s.size() > 40 ? s.substr(0, 37) + "..." : s) + "\""; }

// A value as a message shows it, without dumping a container (a document can
// be large, and dump() recurses as deep as the value).
std::string describe(const nlohmann::json& v) {
    if (v.is_object()) return "an object of " + std::to_string(v.size()) + " members";
    if (v.is_array()) return "an array of " + std::to_string(v.size()) + " elements";
    if (v.is_string()) return quoteShort(v.get_ref<const std::string&>());
    return v.dump();  // a number, true, false or null: short
}

// Line and column (1-based, in bytes) of a byte offset, as in nlohmann's messages.
std::string lineColumn(const std::string& text, size_t offset) {
    offset = std::min(offset, text.size());
    size_t line = 1, lineStart = 0;
    for (size_t i = 0; i < offset; ++i)
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    return "line " + std::to_string(line) + ", column " + std::to_string(offset - lineStart);
}

// A first pass over the text with nlohmann's SAX interface (iterative, so any
// depth is safe here) that refuses what the DOM parser would accept silently
// or the code after it could not survive, naming the JSON pointer.
class JsonChecker : public nlohmann::json_sax<nlohmann::json> {
public:
    JsonChecker(const std::string& text, const std::string& source) : text_(text), source_(source) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(string_t& k) override {
        Level& l = levels_.back();
        l.key = k;
        if (!l.keys.insert(k).second) fail(pointer(), "member " + quoteShort(k) + " given twice");
        return true;
    }
    bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) override {
        if (e.id == 406)  // out_of_range: a number beyond the double range
            fail(pointer(), "number " + token.substr(0, 40) + " is out of the range of a double (" +
                                lineColumn(text_, position) + ")");
        // e.what(): "[json.exception.parse_error.101] parse error at line L, column C: ..."
        std::string what = e.what();
        const auto pos = what.find("] ");
        if (pos != std::string::npos) what = what.substr(pos + 2);
        throw InputError(source_ + ": malformed JSON: " + what);
    }

private:
    struct Level {
        bool array = false;
        size_t count = 0;  // array: elements completed (the current one's index)
        std::string key;   // object: the current member
        std::set<std::string> keys;
    };

    bool value() {
        if (!levels_.empty() && levels_.back().array) ++levels_.back().count;
        return true;
    }
    bool open(bool array) {
        if (int(levels_.size()) >= kMaxJsonDepth)
            fail(pointer(), "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        levels_.push_back(Level{array, 0, {}, {}});
        return true;
    }
    bool close() {
        levels_.pop_back();
        return value();
    }
    // The pointer of the value being read.
    std::string pointer() const {
        std::string p;
        for (const Level& l : levels_) {
            p += '/';
            p += l.array ? std::to_string(l.count) : escapePointerToken(l.key);
        }
        return p;
    }
    [[noreturn]] void fail(const std::string& pointer, const std::string& problem) const {
        throw InputError(source_ + ": " + (pointer.empty() ? std::string("/") : pointer) + ": " + problem);
    }

    const std::string& text_;
    const std::string& source_;
    std::vector<Level> levels_;
};
}  // namespace

JsonReader::JsonReader(const nlohmann::json& value, std::string source, std::string pointer)
    : value_(&value), source_(std::move(source)), pointer_(std::move(pointer)) {}

void JsonReader::checkSize(uintmax_t bytes, const std::string& source) {
    if (bytes > kMaxJsonBytes)
        throw InputError(source + ": " + std::to_string(bytes) + " bytes of JSON; the limit is " +
                         std::to_string(kMaxJsonBytes) + " bytes");
}

nlohmann::json JsonReader::parse(const std::string& text, const std::string& source) {
    checkSize(text.size(), source);
    JsonChecker checker(text, source);
    nlohmann::json::sax_parse(text, &checker);
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        // The checker has seen every problem the parser reports.
        throw std::logic_error(std::string("JsonReader::parse: ") + e.what());
    }
}

void JsonReader::fail(const std::string& problem) const {
    throw InputError(source_ + ": " + (pointer_.empty() ? std::string("/") : pointer_) + ": " + problem);
}

void JsonReader::failOverBudget(const std::string& problem) const {
    throw InputError::overBudget("", source_ + ": " + (pointer_.empty() ? std::string("/") : pointer_) + ": " + problem);
}

bool JsonReader::has(const std::string& key) const { return value_->is_object() && value_->contains(key); }

JsonReader JsonReader::at(const std::string& key) const {
    if (!value_->is_object()) fail("expected an object");
    auto it = value_->find(key);
    if (it == value_->end()) fail("missing required member \"" + key + "\"");
    return JsonReader(*it, source_, pointer_ + "/" + escapePointerToken(key));
}

JsonReader JsonReader::at(size_t index) const {
    if (!value_->is_array()) fail("expected an array");
    if (index >= value_->size()) fail("array too short");
    return JsonReader((*value_)[index], source_, pointer_ + "/" + std::to_string(index));
}

std::optional<JsonReader> JsonReader::find(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    return at(key);
}

void JsonReader::expectObject(std::initializer_list<const char*> known) const {
    if (!value_->is_object()) fail("expected an object, got " + describe(*value_));
    for (auto it = value_->begin(); it != value_->end(); ++it) {
        bool ok = false;
        for (const char* k : known) ok = ok || it.key() == k;
        if (!ok) {
            std::string list;
            for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
            JsonReader(*it, source_, pointer_ + "/" + escapePointerToken(it.key()))
                .fail("unknown member (expected one of: " + list + ")");
        }
    }
}

size_t JsonReader::arraySize() const {
    if (!value_->is_array()) fail("expected an array, got " + describe(*value_));
    return value_->size();
}

double JsonReader::number(double min, double max) const {
    if (!value_->is_number()) fail("expected a number, got " + describe(*value_));
    const double v = value_->get<double>();
    if (!std::isfinite(v)) fail("must be finite");
    if (v < min || v > max)
        fail("must be in [" + formatValue(min) + ", " + formatValue(max) + "], got " + formatValue(v));
    return v;
}

double JsonReader::number(const std::string& key, double fallback, double min, double max) const {
    auto r = find(key);
    return r ? r->number(min, max) : fallback;
}

long long JsonReader::wideInteger(long long min, long long max) const {
    if (!value_->is_number_integer()) fail("expected an integer, got " + describe(*value_));
    const auto outOfRange = [&](const std::string& got) {
        fail("must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + got);
    };
    // A JSON integer above the long long range is unsigned: compare (and show) it as such.
    if (value_->is_number_unsigned()) {
        const uint64_t u = value_->get<uint64_t>();
        if (max < 0 || u > uint64_t(max) || (long long)u < min) outOfRange(std::to_string(u));
        return (long long)u;
    }
    const long long v = value_->get<long long>();
    if (v < min || v > max) outOfRange(std::to_string(v));
    return v;
}

int JsonReader::integer(int min, int max) const { return int(wideInteger(min, max)); }

uint32_t JsonReader::uint32() const { return uint32_t(wideInteger(0, std::numeric_limits<uint32_t>::max())); }

uint32_t JsonReader::uint32(const std::string& key, uint32_t fallback) const {
    auto r = find(key);
    return r ? r->uint32() : fallback;
}

int JsonReader::integer(const std::string& key, int fallback, int min, int max) const {
    auto r = find(key);
    return r ? r->integer(min, max) : fallback;
}

bool JsonReader::boolean(const std::string& key, bool fallback) const {
    auto r = find(key);
    if (!r) return fallback;
    if (!r->value().is_boolean()) r->fail("expected true or false, got " + describe(r->value()));
    return r->value().get<bool>();
}

std::string JsonReader::string() const {
    if (!value_->is_string()) fail("expected a string, got " + describe(*value_));
    return value_->get<std::string>();
}

std::string JsonReader::string(const std::string& key, const std::string& fallback) const {
    auto r = find(key);
    return r ? r->string() : fallback;
}

std::string JsonReader::choice(std::initializer_list<const char*> choices) const {
    const std::string s = string();
    std::string list;
    for (const char* c : choices) {
        if (s == c) return s;
        list += std::string(list.empty() ? "" : ", ") + c;
    }
    failUnknown(s, list);
}

void JsonReader::failUnknown(const std::string& value, const std::string& expected) const {
    // The expected names, ", "-separated, are the candidates for a typo.
    std::vector<std::string> names;
    for (size_t at = 0; at < expected.size();) {
        const size_t comma = std::min(expected.find(", ", at), expected.size());
        names.push_back(expected.substr(at, comma - at));
        at = comma + 2;
    }
    fail("unknown value " + quoteShort(value) + didYouMean(value, names) + " (expected one of: " + expected + ")");
}

std::string JsonReader::choice(const std::string& key, const std::string& fallback,
                               std::initializer_list<const char*> choices) const {
    auto r = find(key);
    return r ? r->choice(choices) : fallback;
}

}  // namespace stochtex
