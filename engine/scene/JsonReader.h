#pragma once
// Typed, strict reading of JSON documents with errors that name the JSON
// pointer of the offending value ("/lights/1/intensity: must be >= 0, got -2").
//
// Errors are sticky: the first one is kept and every later read is a no-op, so
// a loader reads all its fields in sequence and checks JsonContext::failed()
// once at the end instead of after every field.

#include "core/Result.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace dermis {

// Larger inputs are refused before parsing (scene files are a few KiB).
constexpr size_t kMaxJsonTextBytes = size_t(16) << 20;
// Arrays and objects nested deeper are refused (a scene needs five levels).
constexpr size_t kMaxNestingDepth = 256;

// Parses text as strict JSON (no comments, no trailing data, no duplicate
// keys). Errors carry `where` and one line with the line and column.
Result<nlohmann::json> parseJsonText(const std::string& text, const std::string& where);

// Escapes a key for use as one JSON pointer segment in a message ('~' -> "~0",
// '/' -> "~1", control characters -> "\u000a" to keep messages on one line).
std::string jsonPointerSegment(const std::string& key);

// A quoted, escaped and shortened copy of s for messages (always one line).
std::string quoteForMessage(const std::string& s);

// "directional, spot or point"
std::string listForMessage(const std::vector<std::string>& items, const char* lastSeparator);
// ": did you mean "NAME"?" when one of `known` is a likely typo of `given` (core/Suggest.h), else "".
std::string suggestionForMessage(const std::string& given, const std::vector<std::string>& known);

// What a number that overflowed while parsing is told (the range of finite doubles).
inline const std::string kBeyondDoubles = " (finite numbers reach about +-1.8e308)";

// The shortest text that reads back as x ("0.05", "1e+39").
std::string formatNumberForMessage(double x);
std::string formatNumberForMessage(float x);

// "a number", "a string", "an array", ...
std::string jsonTypeForMessage(const nlohmann::json& value);

// An allowed interval for a number; open or closed at either end.
struct Range {
    double low = -1e300;
    double high = 1e300;
    bool lowOpen = false;
    bool highOpen = false;

    static Range any() { return {}; }
    static Range atLeast(double low) { return {low, 1e300, false, false}; }
    static Range above(double low) { return {low, 1e300, true, false}; }
    static Range closed(double low, double high) { return {low, high, false, false}; }
    static Range open(double low, double high) { return {low, high, true, true}; }
    static Range leftOpen(double low, double high) { return {low, high, true, false}; }
    static Range rightOpen(double low, double high) { return {low, high, false, true}; }

    bool contains(double x) const;
    std::string describe() const;  // "must be > 0", "must be in (0, 180)"
};

class JsonContext {
public:
    explicit JsonContext(std::string where) : mWhere(std::move(where)) {}

    bool failed() const { return mError.has_value(); }
    const Error& error() const { return *mError; }
    const std::string& where() const { return mWhere; }

    // Records problem at pointer unless an earlier error was recorded.
    void fail(const std::string& pointer, const std::string& problem);
    // fail() unless condition holds; returns condition.
    bool check(bool condition, const std::string& pointer, const std::string& problem);

private:
    std::string mWhere;
    std::optional<Error> mError;
};

// Reads the members of one JSON object. Construction checks that the value is
// an object and that it has no keys outside `known`.
class JsonObject {
public:
    JsonObject(JsonContext& context, const nlohmann::json& value, std::string pointer,
               const std::vector<std::string>& known);

    bool has(const char* key) const;
    std::string pointer(const char* key) const { return mPointer + "/" + jsonPointerSegment(key); }
    const std::string& pointer() const { return mPointer; }
    JsonContext& context() const { return mContext; }

    // Each reader leaves `out` unchanged when the key is absent or on error.
    void number(const char* key, float& out, const Range& range = Range::any());
    void integer(const char* key, int& out, const Range& range = Range::any());
    void boolean(const char* key, bool& out);
    void string(const char* key, std::string& out, bool allowEmpty = true);
    // An array of exactly 3 numbers, each within `range`.
    void vec3(const char* key, glm::vec3& out, const Range& range = Range::any());
    // A string from `options`; out becomes its index. `noun` names the enum in
    // messages: unknown <noun> "x" (expected a, b or c).
    void choice(const char* key, const char* noun, const std::vector<std::string>& options, int& out);

    // The member, or nullptr when absent or after an error.
    const nlohmann::json* member(const char* key) const;
    // The member as an array of at most maxSize elements, or nullptr.
    const nlohmann::json* array(const char* key, size_t maxSize, const char* elementNoun);

private:
    bool readFloat(const nlohmann::json& value, const std::string& where, const Range& range, float& out);

    JsonContext& mContext;
    const nlohmann::json* mValue = nullptr;  // null when not an object
    std::string mPointer;
};

}  // namespace dermis
