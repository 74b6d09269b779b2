#include "stochtex/workbench/json_layout.h"

#include <cctype>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace stochtex {

namespace {

// Where a value sits in the original text, and its members' places.
struct Span {
    size_t begin = 0, end = 0;
    size_t keyBegin = std::string::npos;  // an object member's: where its key starts
    std::vector<std::pair<std::string, Span>> members;  // an object's, in the text's order
    std::vector<Span> items;                            // an array's
    bool multiline = false;
};

// A scanner over text already known to be valid JSON: it only finds where
// each value starts and ends.
class Scanner {
public:
    explicit Scanner(const std::string& text) : t_(text) {}

    Span value() {
        skip();
        Span s;
        s.begin = i_;
        const char c = t_.at(i_);
        if (c == '{' || c == '[') {
            const char close = c == '{' ? '}' : ']';
            ++i_;
            skip();
            while (t_.at(i_) != close) {
                if (c == '{') {
                    const size_t keyBegin = i_;
                    string();
                    std::string key = nlohmann::json::parse(t_.substr(keyBegin, i_ - keyBegin)).get<std::string>();
                    skip();
                    ++i_;  // ':'
                    s.members.emplace_back(std::move(key), value());
                    s.members.back().second.keyBegin = keyBegin;
                } else {
                    s.items.push_back(value());
                }
                skip();
                if (t_.at(i_) == ',') ++i_, skip();
            }
            ++i_;
        } else if (c == '"') {
            string();
        } else {
            while (i_ < t_.size() && !std::isspace(static_cast<unsigned char>(t_[i_])) && t_[i_] != ',' &&
                   t_[i_] != '}' && t_[i_] != ']')
                ++i_;
        }
        s.end = i_;
        s.multiline = t_.find('\n', s.begin) < s.end;
        return s;
    }

private:
    void skip() {
        while (i_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[i_]))) ++i_;
    }
    void string() {
        ++i_;  // the opening quote
        while (t_.at(i_) != '"') i_ += t_[i_] == '\\' ? 2 : 1;
        ++i_;
    }
    const std::string& t_;
    size_t i_ = 0;
};

class Writer {
public:
    explicit Writer(const std::string& text) : t_(text) {}

    // `value` where `orig` (may be null) was; `indent`: the spaces its line starts with.
    void write(const nlohmann::json& value, const Span* orig, const std::string& indent) {
        if (orig && nlohmann::json::parse(t_.substr(orig->begin, orig->end - orig->begin)) == value) {
            out += t_.substr(orig->begin, orig->end - orig->begin);
            return;
        }
        const bool sameKind = orig && ((value.is_object() && t_[orig->begin] == '{') ||
                                       (value.is_array() && t_[orig->begin] == '['));
        if (!value.is_structured() || value.empty()) {
            out += value.dump();
            return;
        }
        const bool multiline = sameKind && orig->multiline;
        const std::string inner = multiline ? memberIndent(*orig, indent) : indent;
        const char* open = value.is_object() ? "{" : "[";
        const char* close = value.is_object() ? "}" : "]";
        out += open;
        bool first = true;
        auto separate = [&] {
            out += first ? "" : ",";
            out += multiline ? "\n" + inner : first ? "" : " ";
            first = false;
        };
        if (value.is_object()) {
            // The original's keys in its order, then the new ones.
            std::vector<std::pair<std::string, const Span*>> keys;
            if (sameKind)
                for (const auto& [key, span] : orig->members)
                    if (value.contains(key)) keys.emplace_back(key, &span);
            for (const auto& [key, child] : value.items()) {
                bool known = false;
                for (const auto& k : keys) known = known || k.first == key;
                if (!known) keys.emplace_back(key, nullptr);
            }
            for (const auto& [key, span] : keys) {
                separate();
                out += nlohmann::json(key).dump() + ": ";
                write(value.at(key), span, inner);
            }
        } else {
            for (size_t k = 0; k < value.size(); ++k) {
                separate();
                write(value[k], sameKind && k < orig->items.size() ? &orig->items[k] : nullptr, inner);
            }
        }
        if (multiline) out += "\n" + indent;
        out += close;
    }

    std::string out;

private:
    // The spaces before the original's first member on its line, or two more than the container's.
    std::string memberIndent(const Span& s, const std::string& indent) const {
        const Span* first = !s.members.empty() ? &s.members.front().second : !s.items.empty() ? &s.items.front() : nullptr;
        if (first) {
            const size_t at = first->keyBegin != std::string::npos ? first->keyBegin : first->begin;
            const size_t line = t_.rfind('\n', at);
            if (line != std::string::npos && line > s.begin) {
                const std::string lead = t_.substr(line + 1, at - line - 1);
                if (lead.find_first_not_of(' ') == std::string::npos) return lead;
            }
        }
        return indent + "  ";
    }
    const std::string& t_;
};

}  // namespace

std::string layoutLike(const nlohmann::json& value, const std::string& original) {
    if (original.empty()) return value.dump(2);
    if (!nlohmann::json::accept(original)) throw std::invalid_argument("layoutLike: the original is not JSON");
    Scanner scanner(original);
    const Span root = scanner.value();
    Writer w(original);
    // The text around the root value (a leading comment cannot be; a final newline can).
    w.out = original.substr(0, root.begin);
    w.write(value, &root, "");
    w.out += original.substr(root.end);
    return w.out;
}

}  // namespace stochtex
