#include "core/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "core/printable.h"

namespace eikon::json {

namespace {

// Short values are quoted in full in messages; longer ones are summarised so that one error
// stays one readable line.
constexpr std::size_t kMaxQuotedValueLength = 40;

std::string formatNumber(double x) {
    std::ostringstream out;
    out.precision(std::numeric_limits<double>::max_digits10 - 2);
    out << x;
    return out.str();
}

// Keys come from the user's file: control characters in them are escaped (core/printable.h).
std::string quote(const std::string& text) {
    return "'" + printable(text) + "'";
}

// Deeper than any scene needs, shallow enough that nothing (the parser's stacks, a recursive
// destructor, our pointers) grows with a hostile file: 100,000 levels ended in bad_alloc.
constexpr std::size_t kMaxNestingDepth = 256;

std::string joinQuoted(const std::vector<std::string>& items, const std::string& quoteMark) {
    std::string joined;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) joined += ", ";
        joined += quoteMark + items[i] + quoteMark;
    }
    return joined;
}

// Lower case without '_', so that "Cone_Angle_Deg" and "coneangledeg" compare equal.
std::string foldForComparison(const std::string& word) {
    std::string folded;
    for (char c : word) {
        if (c == '_' || c == '-') continue;
        folded += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return folded;
}

// How many edits apart two words may be and still look like a typo of one another. Short words
// get little slack, or every one-letter key would "match" every other.
std::size_t typoBudget(std::size_t longerLength) {
    if (longerLength <= 2) return 0;
    if (longerLength == 3) return 1;
    if (longerLength <= 5) return 2;
    return 3;
}

// ---- syntax errors -------------------------------------------------------------------------

struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};

// nlohmann reports the 1-based byte index of the last character read; turn it into a line and a
// column that counts characters (UTF-8 continuation bytes are not columns of their own).
TextPosition positionOfByte(const std::string& text, std::size_t byte) {
    const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
    TextPosition position;
    for (std::size_t i = 0; i < end; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++position.line;
            position.column = 1;
        } else if ((c & 0xC0) != 0x80) {
            ++position.column;
        }
    }
    return position;
}

// nlohmann's message starts with "[json.exception...] parse error at line L, column C: " (with
// its own byte-based position); keep only the description after that.
std::string syntaxErrorDetail(const std::string& what) {
    const std::size_t syntax = what.find("syntax error");
    if (syntax != std::string::npos) return what.substr(syntax);
    const std::size_t bracket = what.find("] ");
    return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

// ---- duplicate keys ------------------------------------------------------------------------

// Follows the parser's events to know the pointer of each object, so that a repeated key can
// be reported where it is. nlohmann keeps the last of two equal keys without a word; in a hand
// written scene that hides a mistake.
class DuplicateKeyChecker {
public:
    explicit DuplicateKeyChecker(std::string file) : file_(std::move(file)) {}

    bool onEvent(Json::parse_event_t event, const Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
                open(false);
                break;
            case Json::parse_event_t::array_start:
                open(true);
                break;
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end:
                frames_.pop_back();
                break;
            case Json::parse_event_t::key:
                addKey(parsed.get<std::string>());
                break;
            case Json::parse_event_t::value:
                if (!frames_.empty() && frames_.back().isArray) ++frames_.back().count;
                break;
        }
        return true;
    }

    // The pointer of the value being parsed now: after a key, that key's; in an array, the next
    // element's. Where a number that overflows is, for its message.
    std::string currentPointer() const {
        if (frames_.empty()) return "";
        const Frame& frame = frames_.back();
        return appendPointer(frame.pointer,
                             frame.isArray ? std::to_string(frame.count) : frame.lastKey);
    }

private:
    struct Frame {
        bool isArray = false;
        std::size_t count = 0;  // elements seen so far (arrays)
        std::string pointer;
        std::string lastKey;  // objects
        std::vector<std::string> keys;
    };

    void open(bool isArray) {
        if (frames_.size() >= kMaxNestingDepth)
            throw Error(file_, "nested deeper than " + std::to_string(kMaxNestingDepth) +
                                   " arrays and objects (at " + printable(currentPointer(), 60) +
                                   ")");
        Frame frame;
        frame.isArray = isArray;
        if (!frames_.empty()) {
            Frame& parent = frames_.back();
            const std::string segment =
                parent.isArray ? std::to_string(parent.count++) : parent.lastKey;
            frame.pointer = appendPointer(parent.pointer, segment);
        }
        frames_.push_back(std::move(frame));
    }

    void addKey(const std::string& key) {
        Frame& frame = frames_.back();
        const std::string pointer = appendPointer(frame.pointer, key);
        if (std::find(frame.keys.begin(), frame.keys.end(), key) != frame.keys.end()) {
            throw Error(file_ + ":" + pointer,
                        "duplicate key " + quote(key) + "; each key may appear once per object");
        }
        frame.keys.push_back(key);
        frame.lastKey = key;
    }

    std::string file_;
    std::vector<Frame> frames_;
};

}  // namespace

Json parseDocument(const std::string& text, const std::string& file) {
    DuplicateKeyChecker checker(file);
    try {
        return Json::parse(text, [&checker](int, Json::parse_event_t event, Json& parsed) {
            return checker.onEvent(event, parsed);
        });
    } catch (const Json::parse_error& e) {
        const TextPosition at = positionOfByte(text, e.byte);
        throw Error(file, "invalid JSON at line " + std::to_string(at.line) + ", column " +
                              std::to_string(at.column) + ": " +
                              printable(syntaxErrorDetail(e.what()), 200));
    } catch (const Json::out_of_range& e) {
        // 406: a number beyond a double ("1e400"); nlohmann gives no position, the checker knows
        // the pointer of the value it was reading.
        const std::string what = e.what();
        const std::size_t parsing = what.find("parsing '");
        const std::string number = parsing == std::string::npos
                                       ? ""
                                       : what.substr(parsing + 9, what.size() - parsing - 10);
        throw Error(file + ":" + checker.currentPointer(),
                    "the number " + printable(number) +
                        " is out of range (a double reaches about 1.8e308)");
    } catch (const Json::exception& e) {
        throw Error(file + ":" + checker.currentPointer(),
                    "invalid JSON: " + printable(syntaxErrorDetail(e.what()), 200));
    }
}

// ---- Range -----------------------------------------------------------------------------------

Range Range::any() {
    const double inf = std::numeric_limits<double>::infinity();
    return {-inf, inf};
}
Range Range::atLeast(double lo) {
    return {lo, std::numeric_limits<double>::infinity()};
}
Range Range::greaterThan(double lo) {
    return {lo, std::numeric_limits<double>::infinity(), true, false};
}
Range Range::closed(double lo, double hi) {
    return {lo, hi};
}
Range Range::open(double lo, double hi) {
    return {lo, hi, true, true};
}
Range Range::closedOpen(double lo, double hi) {
    return {lo, hi, false, true};
}
Range Range::openClosed(double lo, double hi) {
    return {lo, hi, true, false};
}

bool Range::contains(double x) const {
    const bool aboveLo = loOpen ? x > lo : x >= lo;
    const bool belowHi = hiOpen ? x < hi : x <= hi;
    return aboveLo && belowHi;
}

std::string Range::describe() const {
    const bool boundedLo = std::isfinite(lo);
    const bool boundedHi = std::isfinite(hi);
    if (boundedLo && boundedHi) {
        return std::string("in ") + (loOpen ? "(" : "[") + formatNumber(lo) + ", " +
               formatNumber(hi) + (hiOpen ? ")" : "]");
    }
    if (boundedLo) return (loOpen ? "> " : ">= ") + formatNumber(lo);
    if (boundedHi) return (hiOpen ? "< " : "<= ") + formatNumber(hi);
    return "";
}

// ---- free helpers ----------------------------------------------------------------------------

std::string describeValue(const Json& value) {
    // dump() escapes the control characters below 0x20 as JSON does, but not DEL (0x7f), which
    // printable() then writes as \x7f.
    const std::string text = printable(value.dump(), std::string::npos);
    if (text.size() <= kMaxQuotedValueLength) return text;
    if (value.is_array()) return "an array of " + std::to_string(value.size()) + " elements";
    if (value.is_object()) return "an object with " + std::to_string(value.size()) + " keys";
    if (value.is_string()) return text.substr(0, kMaxQuotedValueLength - 4) + "...\"";
    return text;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
    // Optimal string alignment: Levenshtein plus adjacent transpositions ("widht" is one edit
    // from "width"), over the full table since keys are short.
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[a.size()][b.size()];
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string folded = foldForComparison(word);
    std::string best;
    std::size_t bestDistance = SIZE_MAX;
    for (const std::string& candidate : candidates) {
        const std::string foldedCandidate = foldForComparison(candidate);
        const std::size_t distance = editDistance(folded, foldedCandidate);
        const std::size_t budget = typoBudget(std::max(folded.size(), foldedCandidate.size()));
        if (distance <= budget && distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

std::string appendPointer(const std::string& pointer, const std::string& key) {
    std::string escaped;
    for (char c : key) {
        if (c == '~') {
            escaped += "~0";
        } else if (c == '/') {
            escaped += "~1";
        } else {
            escaped += c;
        }
    }
    // The key is the user's bytes and the pointer goes into messages as their where(): a tab or
    // a line end in a key must not reach the terminal raw.
    return pointer + "/" + printable(escaped);
}

// ---- Value -----------------------------------------------------------------------------------

Value::Value(const Json& json, std::string file, std::string pointer)
    : json_(&json), file_(std::move(file)), pointer_(std::move(pointer)) {}

std::string Value::where() const {
    return pointer_.empty() ? file_ : file_ + ":" + pointer_;
}

void Value::fail(const std::string& reason) const {
    throw Error(where(), reason);
}

void Value::failExpected(const std::string& form) const {
    fail("expected " + form + ", got " + describeValue(*json_));
}

bool Value::isString(const std::string& text) const {
    return json_->is_string() && json_->get_ref<const std::string&>() == text;
}

double Value::number(const Range& range) const {
    const std::string form = range.describe().empty() ? "a number" : "a number " + range.describe();
    if (!json_->is_number()) failExpected(form);
    const double x = json_->get<double>();
    // JSON has no NaN or Inf, but a huge literal (1e999) overflows to Inf when read.
    if (!std::isfinite(x) || !range.contains(x)) failExpected(form);
    return x;
}

float Value::floatNumber(const Range& range) const {
    const double x = number(range);
    if (std::abs(x) > static_cast<double>(std::numeric_limits<float>::max())) {
        failExpected("a number that fits a 32-bit float");
    }
    return static_cast<float>(x);
}

std::int64_t Value::integer(std::int64_t lo, std::int64_t hi) const {
    const std::string form =
        "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (json_->is_number_unsigned()) {
        const std::uint64_t x = json_->get<std::uint64_t>();
        if (hi < 0 || x > static_cast<std::uint64_t>(hi)) failExpected(form);
        const auto value = static_cast<std::int64_t>(x);
        if (value < lo) failExpected(form);
        return value;
    }
    if (json_->is_number_integer()) {
        const std::int64_t x = json_->get<std::int64_t>();
        if (x < lo || x > hi) failExpected(form);
        return x;
    }
    if (json_->is_number_float()) {
        const double x = json_->get<double>();
        const bool whole = std::isfinite(x) && std::floor(x) == x;
        if (!whole || x < static_cast<double>(lo) || x > static_cast<double>(hi)) {
            failExpected(form);
        }
        return static_cast<std::int64_t>(x);
    }
    failExpected(form);
}

bool Value::boolean() const {
    if (!json_->is_boolean()) failExpected("true or false");
    return json_->get<bool>();
}

// Scene strings are names, paths and choices: a control character in one is a mistake, and a
// NUL would cut a path short (output.name "a\u0000b" once made the cleanup rmdir the output
// folder).
std::string Value::string() const {
    if (!json_->is_string()) failExpected("a string");
    if (hasControlCharacter(json_->get_ref<const std::string&>()))
        failExpected("a string without control characters");
    return json_->get<std::string>();
}

std::string Value::nonEmptyString() const {
    if (!json_->is_string() || json_->get_ref<const std::string&>().empty()) {
        failExpected("a non-empty string");
    }
    return string();
}

std::string Value::choice(const std::vector<std::string>& allowed) const {
    const std::string form = "one of " + joinQuoted(allowed, "\"");
    if (!json_->is_string()) failExpected(form);
    const std::string& text = json_->get_ref<const std::string&>();
    if (std::find(allowed.begin(), allowed.end(), text) != allowed.end()) return text;
    std::string reason = "expected " + form + ", got " + describeValue(*json_);
    const std::string suggestion = closestMatch(text, allowed);
    if (!suggestion.empty()) reason += "; did you mean \"" + suggestion + "\"?";
    fail(reason);
}

glm::vec3 Value::vec3(const Range& range) const {
    const std::string each = range.describe();
    const std::string form =
        each.empty() ? "an array of 3 numbers [x, y, z]" : "an array of 3 numbers " + each;
    if (!json_->is_array() || json_->size() != 3) failExpected(form);
    for (const Json& component : *json_) {
        if (!component.is_number()) failExpected(form);
    }
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = element(static_cast<std::size_t>(i)).floatNumber(range);
    return v;
}

glm::ivec3 Value::ivec3(int lo, int hi) const {
    const std::string form =
        "an array of 3 integers in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!json_->is_array() || json_->size() != 3) failExpected(form);
    for (const Json& component : *json_) {
        if (!component.is_number()) failExpected(form);
    }
    glm::ivec3 v;
    for (int i = 0; i < 3; ++i) {
        v[i] = static_cast<int>(element(static_cast<std::size_t>(i)).integer(lo, hi));
    }
    return v;
}

std::vector<Value> Value::elements(const std::string& form, std::size_t maxSize) const {
    if (!json_->is_array()) failExpected(form);
    if (json_->size() > maxSize) {
        fail("expected at most " + std::to_string(maxSize) + " elements in " + form + ", got " +
             std::to_string(json_->size()));
    }
    std::vector<Value> values;
    values.reserve(json_->size());
    for (std::size_t i = 0; i < json_->size(); ++i) values.push_back(element(i));
    return values;
}

Value Value::child(const std::string& key) const {
    return Value(json_->at(key), file_, appendPointer(pointer_, key));
}

Value Value::element(std::size_t index) const {
    return Value(json_->at(index), file_, appendPointer(pointer_, std::to_string(index)));
}

// ---- Object ----------------------------------------------------------------------------------

Object::Object(const Value& value, std::string kind) : value_(value), kind_(std::move(kind)) {
    if (!value_.isObject())
        value_.failExpected(kind_.empty() ? "an object" : kind_ + " (an object)");
}

bool Object::has(const std::string& key) const {
    return value_.json().contains(key);
}

void Object::expect(const std::string& key) {
    if (std::find(expectedKeys_.begin(), expectedKeys_.end(), key) == expectedKeys_.end()) {
        expectedKeys_.push_back(key);
    }
}

std::optional<Value> Object::optional(const std::string& key) {
    expect(key);
    if (!has(key)) return std::nullopt;
    return value_.child(key);
}

Value Object::required(const std::string& key, const std::string& form) {
    expect(key);
    if (!has(key)) {
        std::string reason = "missing required key " + quote(key) + " (" + form + ")";
        // A misspelt required key would otherwise be reported as missing with no word about the
        // key the user did write.
        const std::string typo = closestMatch(key, unexpectedKeys());
        if (!typo.empty()) reason += "; is " + quote(typo) + " a misspelling of it?";
        failAt(key, reason);
    }
    return value_.child(key);
}

std::vector<std::string> Object::unexpectedKeys() const {
    std::vector<std::string> keys;
    for (const auto& item : value_.json().items()) {
        if (std::find(expectedKeys_.begin(), expectedKeys_.end(), item.key()) ==
            expectedKeys_.end()) {
            keys.push_back(item.key());
        }
    }
    return keys;
}

void Object::failAt(const std::string& key, const std::string& reason) const {
    throw Error(value_.file() + ":" + appendPointer(value_.pointer(), key), reason);
}

void Object::forbid(const std::string& key, const std::string& reason) {
    if (has(key)) value_.child(key).fail(reason);
}

void Object::finish() const {
    for (const std::string& key : unexpectedKeys()) {
        std::string reason = "unknown key " + quote(key);
        if (!kind_.empty()) reason += " for " + kind_;
        const std::string suggestion = closestMatch(key, expectedKeys_);
        if (!suggestion.empty()) reason += " (did you mean " + quote(suggestion) + "?)";
        if (expectedKeys_.empty()) {
            reason += "; this object takes no keys";
        } else {
            reason += "; expected one of: " + joinQuoted(expectedKeys_, "");
        }
        value_.child(key).fail(reason);
    }
}

}  // namespace eikon::json
