#pragma once
// A strict reader over nlohmann::json for files users write by hand (scenes). Every value knows
// its JSON pointer ("/lights/0/intensity"), so each error is an eikon::Error whose where() is
// "<file>:<pointer>" and whose reason states the expected form and what was found instead:
//     smoke.json:/lights/0/intensity: expected a number >= 0, got -1
// Objects are read through json::Object, which remembers the keys asked for and, at finish(),
// rejects any other key with a "did you mean" hint: a misspelt optional key must not be silently
// ignored, or the user would get a default instead of the value they wrote.
//
// Users of the scene model include core/scene.h; this header is for code that reads a section of
// a scene itself: the light-transport methods read their settings with it
// (render/light_transport_registry.h).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace eikon::json {

// Ordered so that "the first unknown key" is the first one in the file, not in sorted order.
using Json = nlohmann::ordered_json;

// Parses a whole document. A syntax error, or a key repeated within one object (which
// nlohmann would otherwise resolve silently by keeping the last), throws eikon::Error naming
// the file with the line and column, or the JSON pointer of the repeated key. The column is that
// of the last character the parser read: the end of the unexpected token.
Json parseDocument(const std::string& text, const std::string& file);

// An interval of allowed numbers, used both to check a value and to say what was expected.
struct Range {
    double lo;
    double hi;
    bool loOpen = false;
    bool hiOpen = false;

    static Range any();
    static Range atLeast(double lo);      // [lo, +inf)
    static Range greaterThan(double lo);  // (lo, +inf)
    static Range closed(double lo, double hi);
    static Range open(double lo, double hi);
    static Range closedOpen(double lo, double hi);  // [lo, hi)
    static Range openClosed(double lo, double hi);  // (lo, hi]

    bool contains(double x) const;
    // ">= 0", "> 0", "in [0, 1)"; empty for any().
    std::string describe() const;
};

// "got ..." text for a value: the value itself when short ("abc" quoted, -1, [1,2]), otherwise
// its kind ("an array of 12 elements", "an object").
std::string describeValue(const Json& value);

// Edit distance (insertions, deletions, substitutions, adjacent transpositions), for hints.
std::size_t editDistance(const std::string& a, const std::string& b);
// The candidate a user most likely meant by `word`, or empty when none is close enough.
// Case and '_' differences count as close ("Intensity", "coneAngleDeg").
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

// Appends a key or index to a JSON pointer, escaping '~' and '/' as RFC 6901 requires. Pointers
// are for messages: control characters in the key are written as printable() does, and a key
// longer than 80 bytes is cut there.
std::string appendPointer(const std::string& pointer, const std::string& key);

// One JSON value and where it sits. Cheap to copy; refers to the document, which must outlive it.
class Value {
public:
    Value(const Json& json, std::string file, std::string pointer);

    const Json& json() const { return *json_; }
    const std::string& file() const { return file_; }
    const std::string& pointer() const { return pointer_; }
    // "<file>:<pointer>", or the file alone for the document root.
    std::string where() const;

    [[noreturn]] void fail(const std::string& reason) const;
    // Throws "expected <form>, got <this value>".
    [[noreturn]] void failExpected(const std::string& form) const;

    bool isString(const std::string& text) const;  // a string equal to `text`, e.g. "auto"
    bool isObject() const { return json_->is_object(); }
    bool isArray() const { return json_->is_array(); }
    bool isNumber() const { return json_->is_number(); }

    double number(const Range& range = Range::any()) const;
    // A number that must also fit a float (1e300 is valid JSON but not a usable float).
    float floatNumber(const Range& range = Range::any()) const;
    // An integer in [lo, hi]; a float with no fractional part (2.0) is accepted.
    std::int64_t integer(std::int64_t lo, std::int64_t hi) const;
    bool boolean() const;
    std::string string() const;
    std::string nonEmptyString() const;
    // One of a fixed list of strings, with a "did you mean" hint when the value is close to one.
    std::string choice(const std::vector<std::string>& allowed) const;
    // [x, y, z], each number in `range` (an element out of range is reported at its own pointer).
    glm::vec3 vec3(const Range& range = Range::any()) const;
    // [x, y, z], each an integer in [lo, hi].
    glm::ivec3 ivec3(int lo, int hi) const;
    // The elements of an array of at most `maxSize` elements; `form` is used in messages
    // ("an array of lights").
    std::vector<Value> elements(const std::string& form, std::size_t maxSize = SIZE_MAX) const;

    Value child(const std::string& key) const;
    Value element(std::size_t index) const;

private:
    const Json* json_;
    std::string file_;
    std::string pointer_;
};

// Reads one JSON object. Ask for every key the object may have (optional(), required(), forbid()),
// then call finish(), which rejects any key that was not asked for.
class Object {
public:
    // `kind` names the object in messages about keys, e.g. "a directional light"; may be empty.
    explicit Object(const Value& value, std::string kind = "");

    const Value& value() const { return value_; }
    // Renames the object once its type is known ("a source" becomes "a sphere source").
    void setKind(std::string kind) { kind_ = std::move(kind); }
    bool has(const std::string& key) const;
    // The value of `key`, or nothing when it is absent.
    std::optional<Value> optional(const std::string& key);
    // The value of `key`; when absent, throws at the key's pointer: "missing required key
    // 'name' (<form>)".
    Value required(const std::string& key, const std::string& form);
    // A key this kind of object must not have (a position on a directional light): an error
    // at the key's pointer with `reason`, rather than a plain "unknown key".
    void forbid(const std::string& key, const std::string& reason);
    // Throws at the first key (in file order) that was never asked for, listing the expected
    // keys and the closest one.
    void finish() const;
    // Throws at the pointer of `key`, whether or not it is present: for checks that involve
    // several keys or a default (an "up" vector parallel to the view).
    [[noreturn]] void failAt(const std::string& key, const std::string& reason) const;

private:
    void expect(const std::string& key);
    // The object's keys that were not asked for (so far), in file order.
    std::vector<std::string> unexpectedKeys() const;

    Value value_;
    std::string kind_;
    std::vector<std::string> expectedKeys_;  // in the order asked, for the message
};

}  // namespace eikon::json
