#include "io/JsonTextScan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace hvi::io {

namespace {

using nlohmann::json;

/// How many levels of a too-deep value's pointer the message shows: enough to find the
/// place in the file, short enough to stay one readable line.
constexpr std::size_t kShownLevels = 8;

/// The spellings of non-finite numbers that other tools write (Python's json module,
/// printf, JavaScript).
bool isNonFiniteWord(std::string_view word) {
    return word == "NaN" || word == "nan" || word == "Infinity" || word == "inf" || word == "Inf";
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

bool isLetter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

std::size_t digitsFrom(std::string_view s, std::size_t i) {
    while (i < s.size() && isDigit(s[i])) {
        ++i;
    }
    return i;
}

/// Length of the JSON number (RFC 8259 grammar) at the start of `s`, or 0 if none.
std::size_t numberLength(std::string_view s) {
    std::size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
    if (i < s.size() && s[i] == '0') {
        ++i;
    } else if (i < s.size() && isDigit(s[i])) {
        i = digitsFrom(s, i);
    } else {
        return 0;
    }
    if (i < s.size() && s[i] == '.') {
        const std::size_t end = digitsFrom(s, i + 1);
        if (end == i + 1) {
            return 0;
        }
        i = end;
    }
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        std::size_t start = i + 1;
        if (start < s.size() && (s[start] == '+' || s[start] == '-')) {
            ++start;
        }
        const std::size_t end = digitsFrom(s, start);
        if (end == start) {
            return 0;
        }
        i = end;
    }
    return i;
}

/// Whether a JSON number lies beyond the largest double (about 1.8e308), which the parser
/// refuses without saying where. Only numbers with an exponent or over 300 digits can.
bool beyondDouble(std::string_view number) {
    if (number.size() <= 300 && number.find_first_of("eE") == std::string_view::npos) {
        return false;
    }
    const std::string copy(number);
    return std::isinf(std::strtod(copy.c_str(), nullptr));
}

/// A token as a message shows it: whole when short, else its start and its length.
std::string shown(std::string_view token) {
    if (token.size() <= 40) {
        return std::string(token);
    }
    return std::string(token.substr(0, 20)) + "... (" + std::to_string(token.size()) +
           " characters)";
}

bool isHexDigit(char c) {
    return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

/// Length of the escape (\n, \", \u00e9, ...) at the start of `s`, or 0 if it is not one.
std::size_t escapeLength(std::string_view s) {
    if (s.size() < 2) {
        return 0;
    }
    if (s[1] != 'u') {
        return std::string_view("\"\\/bfnrt").find(s[1]) == std::string_view::npos ? 0 : 2;
    }
    if (s.size() < 6) {
        return 0;
    }
    for (std::size_t i = 2; i < 6; ++i) {
        if (!isHexDigit(s[i])) {
            return 0;
        }
    }
    return 6;
}

/// A key as the document holds it (escapes decoded), from its quoted text.
std::string decodeKey(std::string_view quoted) {
    try {
        return json::parse(quoted).get<std::string>();
    } catch (const json::exception&) {
        return std::string(quoted.substr(1, quoted.size() >= 2 ? quoted.size() - 2 : 0));
    }
}

/// A pushdown scanner: one state and a stack of the open objects and arrays, never a
/// recursive call, so its stack use does not grow with the nesting of the text.
class Scanner {
public:
    Scanner(std::string_view text, const std::string& label, std::size_t maxDepth)
        : m_text(text), m_label(label), m_maxDepth(maxDepth) {}

    JsonTextScan run() {
        if (m_text.substr(0, 3) == "\xEF\xBB\xBF") {
            m_pos = 3; // a UTF-8 byte order mark, which the parser skips too
        }
        while (step()) {
        }
        return std::move(m_result);
    }

private:
    enum class Expect { Value, ValueOrEnd, Key, KeyOrEnd, Colon, CommaOrEnd, Nothing };
    struct Frame {
        bool isObject = false;
        std::size_t index = 0; ///< of the current element, in an array
        std::string_view key;  ///< quoted text of the current key, in an object
    };

    /// Reads one token; false when the scan is over (the end, or text that is not JSON).
    bool step() {
        skipWhitespace();
        if (m_expect == Expect::Nothing) {
            m_result.wellFormed = m_pos == m_text.size();
            return false;
        }
        if (m_pos >= m_text.size()) {
            return false;
        }
        const char c = m_text[m_pos];
        switch (m_expect) {
        case Expect::ValueOrEnd:
            return c == ']' ? close(c) : value(c);
        case Expect::Value:
            return value(c);
        case Expect::KeyOrEnd:
            return c == '}' ? close(c) : key(c);
        case Expect::Key:
            return key(c);
        case Expect::Colon:
            return colon(c);
        case Expect::CommaOrEnd:
            return c == ',' ? comma() : close(c);
        case Expect::Nothing:
            break;
        }
        return false;
    }

    bool value(char c) {
        if (c == '{' || c == '[') {
            return open(c == '{');
        }
        if (c == '"') {
            if (!skipString()) {
                return false;
            }
            afterValue();
            return true;
        }
        return scalar();
    }

    /// A number, true/false/null, or a spelling of NaN or Infinity (with an optional sign).
    bool scalar() {
        const std::string_view rest = m_text.substr(m_pos);
        const std::size_t sign = rest[0] == '-' ? 1 : 0;
        std::size_t end = sign;
        while (end < rest.size() && isLetter(rest[end])) {
            ++end;
        }
        if (end > sign) {
            const std::string_view word = rest.substr(sign, end - sign);
            if (isNonFiniteWord(word)) {
                report(std::string("is ") + std::string(rest.substr(0, end)) +
                       ", not a finite number");
            } else if (sign == 1 || !(word == "true" || word == "false" || word == "null")) {
                return false;
            }
        } else {
            end = numberLength(rest);
            if (end == 0) {
                return false;
            }
            if (beyondDouble(rest.substr(0, end))) {
                report("is " + shown(rest.substr(0, end)) +
                       ", beyond the range of a double (about 1.8e308)");
            }
        }
        m_pos += end;
        afterValue();
        return true;
    }

    bool open(bool isObject) {
        if (m_stack.size() >= m_maxDepth) {
            reportTooDeep();
            return false;
        }
        m_stack.push_back({isObject, 0, {}});
        ++m_pos;
        m_expect = isObject ? Expect::KeyOrEnd : Expect::ValueOrEnd;
        return true;
    }

    bool close(char c) {
        if (m_stack.empty() || c != (m_stack.back().isObject ? '}' : ']')) {
            return false;
        }
        m_stack.pop_back();
        ++m_pos;
        afterValue();
        return true;
    }

    bool key(char c) {
        const std::size_t start = m_pos;
        if (c != '"' || !skipString()) {
            return false;
        }
        m_stack.back().key = m_text.substr(start, m_pos - start);
        m_expect = Expect::Colon;
        return true;
    }

    bool colon(char c) {
        if (c != ':') {
            return false;
        }
        ++m_pos;
        m_expect = Expect::Value;
        return true;
    }

    bool comma() {
        ++m_pos;
        Frame& top = m_stack.back(); // CommaOrEnd is only expected inside a container
        if (top.isObject) {
            m_expect = Expect::Key;
        } else {
            ++top.index;
            m_expect = Expect::Value;
        }
        return true;
    }

    void afterValue() { m_expect = m_stack.empty() ? Expect::Nothing : Expect::CommaOrEnd; }

    /// From an opening quote to just past the closing one; an escaped quote does not end
    /// the string. UTF-8 and surrogate pairs are left to the parser.
    bool skipString() {
        ++m_pos;
        while (m_pos < m_text.size()) {
            const char c = m_text[m_pos];
            if (c == '"') {
                ++m_pos;
                return true;
            }
            if (static_cast<unsigned char>(c) < 0x20) {
                return false; // JSON strings hold no raw control characters
            }
            if (c == '\\') {
                const std::size_t length = escapeLength(m_text.substr(m_pos));
                if (length == 0) {
                    return false;
                }
                m_pos += length;
            } else {
                ++m_pos;
            }
        }
        return false;
    }

    void skipWhitespace() {
        while (m_pos < m_text.size() && (m_text[m_pos] == ' ' || m_text[m_pos] == '\n' ||
                                         m_text[m_pos] == '\r' || m_text[m_pos] == '\t')) {
            ++m_pos;
        }
    }

    /// The JSON pointer of the current value, through at most `levels` containers.
    std::string pointer(std::size_t levels) const {
        json::json_pointer p;
        const std::size_t n = std::min(levels, m_stack.size());
        for (std::size_t i = 0; i < n; ++i) {
            const Frame& f = m_stack[i];
            p /= f.isObject ? decodeKey(f.key) : std::to_string(f.index);
        }
        return p.to_string();
    }

    std::string lineAndColumn() const {
        const std::string_view before = m_text.substr(0, m_pos);
        const auto line = std::count(before.begin(), before.end(), '\n') + 1;
        const auto lastNewline = before.rfind('\n');
        const std::size_t column =
            lastNewline == std::string_view::npos ? m_pos + 1 : m_pos - lastNewline;
        return "line " + std::to_string(line) + ", column " + std::to_string(column);
    }

    void report(const std::string& problem) {
        m_result.nonFinite.push_back(
            {m_label, pointer(m_stack.size()), problem, "a finite number"});
    }

    void reportTooDeep() {
        const std::string limit = std::to_string(m_maxDepth);
        m_result.tooDeep = InputIssue{m_label, pointer(kShownLevels),
                                      "holds objects and arrays nested more than " + limit +
                                          " levels deep, at " + lineAndColumn(),
                                      "at most " + limit + " levels of nested objects and arrays"};
    }

    std::string_view m_text;
    const std::string& m_label;
    std::size_t m_maxDepth;
    std::size_t m_pos = 0;
    Expect m_expect = Expect::Value;
    std::vector<Frame> m_stack;
    JsonTextScan m_result;
};

} // namespace

JsonTextScan scanJsonText(std::string_view text, const std::string& label, std::size_t maxDepth) {
    return Scanner(text, label, maxDepth).run();
}

} // namespace hvi::io
