#pragma once
// Reads a JSON document while remembering where it is, so every validation
// error names the source and the JSON pointer of the offending value, e.g.
//   camouflage.json: /noise_x/components/0/frequency: must be in [0, 10000], got -3
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stochtex/core/enum_names.h"
#include "stochtex/core/error.h"

namespace stochtex {

// Limits of any JSON text read (pattern files, noise and colormap specs):
// a pattern file is a few kB, and a DOM costs ~20× its text in memory; the
// nesting of a pattern is under 10 levels, and a deeper document would only
// exhaust the stack of whatever walks it recursively.
constexpr size_t kMaxJsonBytes = size_t(1) << 20;
constexpr int kMaxJsonDepth = 64;

class JsonReader {
public:
    JsonReader(const nlohmann::json& value, std::string source, std::string pointer = "");

    // Parses text. Every problem is an InputError naming the source: a syntax
    // error (with line and column), text over kMaxJsonBytes, nesting deeper
    // than kMaxJsonDepth, a number that overflows a double and a member given
    // twice in one object (the last would silently win), the last three with
    // the JSON pointer of the value.
    static nlohmann::json parse(const std::string& text, const std::string& source);
    // Fails if a text (or file) of this many bytes is over kMaxJsonBytes.
    static void checkSize(uintmax_t bytes, const std::string& source);

    const nlohmann::json& value() const { return *value_; }
    const std::string& pointer() const { return pointer_; }
    const std::string& source() const { return source_; }

    [[noreturn]] void fail(const std::string& problem) const;
    // The same, for a request beyond a budget (InputError::overBudget).
    [[noreturn]] void failOverBudget(const std::string& problem) const;

    // Runs a library check on values read from this object. A parameter error
    // it raises is re-raised at this object's member of the same name (at the
    // object itself if it has none), e.g.
    //   pattern.json: /size: size must be at most 67108864 pixels, got 10000x10000
    template <class Check>
    void check(Check&& libraryCheck) const {
        try {
            libraryCheck();
        } catch (const InputError& e) {
            if (e.parameter().empty()) throw;
            const JsonReader where = has(e.parameter()) ? at(e.parameter()) : *this;
            if (e.isOverBudget()) where.failOverBudget(e.what());
            where.fail(e.what());
        }
    }

    bool has(const std::string& key) const;
    JsonReader at(const std::string& key) const;  // required member
    JsonReader at(size_t index) const;            // array element
    std::optional<JsonReader> find(const std::string& key) const;

    // Checks this value is an object whose keys are all in `known` (typos fail).
    void expectObject(std::initializer_list<const char*> known) const;
    size_t arraySize() const;  // fails unless an array

    double number(double min, double max) const;
    double number(const std::string& key, double fallback, double min, double max) const;
    int integer(const std::string& key, int fallback, int min, int max) const;
    int integer(int min, int max) const;
    // An integer in [0, 4294967295] (seeds).
    uint32_t uint32() const;
    uint32_t uint32(const std::string& key, uint32_t fallback) const;
    bool boolean(const std::string& key, bool fallback) const;
    std::string string() const;
    std::string string(const std::string& key, const std::string& fallback) const;
    // A string that must be one of `choices`.
    std::string choice(const std::string& key, const std::string& fallback,
                       std::initializer_list<const char*> choices) const;
    std::string choice(std::initializer_list<const char*> choices) const;
    // A string naming a value of an enum's name table (the table the CLI and
    // the bake manifest use); the same message as choice() otherwise.
    template <class E>
    E choice(const EnumNames<E>& names) const {
        const std::string s = string();
        if (const E* v = findEnum(names, s)) return *v;
        failUnknown(s, canonicalNames(names, ", "));
    }
    template <class E>
    E choice(const std::string& key, E fallback, const EnumNames<E>& names) const {
        auto r = find(key);
        return r ? r->choice(names) : fallback;
    }

private:
    // An integer value as a wide type, whatever its JSON sign (fails unless an integer).
    long long wideInteger(long long min, long long max) const;
    [[noreturn]] void failUnknown(const std::string& value, const std::string& expected) const;
    const nlohmann::json* value_;
    std::string source_;
    std::string pointer_;
};

}  // namespace stochtex
