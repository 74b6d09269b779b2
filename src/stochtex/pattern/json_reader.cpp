#include "stochtex/pattern/json_reader.h"

#include <cmath>

#include "stochtex/core/error.h"

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

std::string describe(const nlohmann::json& v) {
    std::string s = v.dump();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}
}  // namespace

JsonReader::JsonReader(const nlohmann::json& value, std::string source, std::string pointer)
    : value_(&value), source_(std::move(source)), pointer_(std::move(pointer)) {}

nlohmann::json JsonReader::parse(const std::string& text, const std::string& source) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        // e.what() carries "[json.exception.parse_error.101] parse error at line L, column C: ..."
        std::string what = e.what();
        const auto pos = what.find("] ");
        if (pos != std::string::npos) what = what.substr(pos + 2);
        throw InputError(source + ": malformed JSON: " + what);
    }
}

void JsonReader::fail(const std::string& problem) const {
    throw InputError(source_ + ": " + (pointer_.empty() ? std::string("/") : pointer_) + ": " + problem);
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

int JsonReader::integer(int min, int max) const {
    if (!value_->is_number_integer()) fail("expected an integer, got " + describe(*value_));
    const long long v = value_->get<long long>();
    if (v < min || v > max)
        fail("must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + std::to_string(v));
    return int(v);
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
    fail("unknown value \"" + value + "\" (expected one of: " + expected + ")");
}

std::string JsonReader::choice(const std::string& key, const std::string& fallback,
                               std::initializer_list<const char*> choices) const {
    auto r = find(key);
    return r ? r->choice(choices) : fallback;
}

}  // namespace stochtex
