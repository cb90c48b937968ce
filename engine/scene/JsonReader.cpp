#include "scene/JsonReader.h"

#include "core/Suggest.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace dermis {

namespace {

using nlohmann::json;

constexpr size_t kMaxQuotedChars = 60;

// Keeps a message on one printable-ASCII line whatever bytes the input had.
std::string printable(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
        const auto byte = static_cast<unsigned char>(c);
        out += (byte >= 0x20 && byte < 0x7f) ? c : '?';
    }
    return out;
}

// "\u000a": control characters in keys and values, written as JSON would.
std::string controlEscape(unsigned char byte) {
    static const char kHex[] = "0123456789abcdef";
    return std::string("\\u00") + kHex[byte >> 4] + kHex[byte & 15];
}

std::string lineAndColumn(const std::string& text, size_t offset) {
    size_t line = 1;
    size_t column = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann prefixes messages with "[json.exception.parse_error.101] ".
std::string withoutExceptionId(const std::string& message) {
    const size_t end = message.find("] ");
    return message.rfind("[json.exception.", 0) == 0 && end != std::string::npos ? message.substr(end + 2) : message;
}

// An nlohmann SAX handler that builds nothing: it tracks where the parser is,
// to name duplicate keys by JSON pointer and to bound nesting (a scene file is
// a handful of levels deep). It stops at the first syntax error.
class StructureChecker {
public:
    bool null() { return value(); }
    bool boolean(bool) { return value(); }
    bool number_integer(json::number_integer_t) { return value(); }
    bool number_unsigned(json::number_unsigned_t) { return value(); }
    bool number_float(json::number_float_t, const json::string_t&) { return value(); }
    bool string(json::string_t&) { return value(); }
    bool binary(json::binary_t&) { return value(); }
    bool start_object(std::size_t) { return open(true); }
    bool start_array(std::size_t) { return open(false); }
    bool key(json::string_t& name) {
        onKey(name);
        return true;
    }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool parse_error(std::size_t, const std::string&, const json::exception&) { return false; }

    bool tooDeep() const { return mTooDeep; }
    // Where the parser is: the pointer of the value it reads (after an
    // exception, the value that threw).
    std::string currentPointer() const {
        std::string pointer;
        for (const Frame& frame : mFrames)
            pointer += "/" + (frame.isObject ? jsonPointerSegment(frame.currentKey) : std::to_string(frame.index));
        return pointer;
    }
    const std::string& duplicatePointer() const { return mDuplicatePointer; }
    const std::string& duplicateKey() const { return mDuplicateKey; }

private:
    struct Frame {
        bool isObject;
        std::set<std::string> keys;
        std::string currentKey;
        size_t index;
    };

    void onKey(const std::string& key) {
        Frame& frame = mFrames.back();
        if (!frame.keys.insert(key).second && mDuplicateKey.empty() && mDuplicatePointer.empty()) {
            for (size_t i = 0; i + 1 < mFrames.size(); ++i) {
                mDuplicatePointer += "/" + (mFrames[i].isObject ? jsonPointerSegment(mFrames[i].currentKey)
                                                                : std::to_string(mFrames[i].index));
            }
            mDuplicatePointer += "/" + jsonPointerSegment(key);
            mDuplicateKey = key;
        }
        frame.currentKey = key;
    }

    bool open(bool isObject) {
        if (mFrames.size() >= kMaxNestingDepth) {
            mTooDeep = true;
            return false;
        }
        mFrames.push_back(Frame{isObject, {}, {}, 0});
        return true;
    }

    bool close() {
        mFrames.pop_back();
        return value();
    }

    // An element of the enclosing array is complete.
    bool value() {
        if (!mFrames.empty() && !mFrames.back().isObject) {
            ++mFrames.back().index;
        }
        return true;
    }

    std::vector<Frame> mFrames;
    bool mTooDeep = false;
    std::string mDuplicatePointer;
    std::string mDuplicateKey;
};

}  // namespace

Result<json> parseJsonText(const std::string& text, const std::string& where) {
    if (text.size() > kMaxJsonTextBytes) {
        return makeError(where, "input is " + std::to_string(text.size()) + " bytes; the limit is " +
                                    std::to_string(kMaxJsonTextBytes) + " bytes");
    }
    StructureChecker checker;
    json document;
    try {
        json::sax_parse(text, &checker);
        if (checker.tooDeep()) {
            return makeError(where, "JSON nested deeper than " + std::to_string(kMaxNestingDepth) + " levels");
        }
        // A second, plain parse builds the document, and throws the syntax
        // error the checker stopped at. (nlohmann's parser with a callback
        // rescans an array after each object in it: quadratic time, minutes
        // for an array of a million objects.)
        document = json::parse(text);
    } catch (const json::parse_error& e) {
        return makeError(where, printable(withoutExceptionId(e.what())));
    } catch (const json::out_of_range& e) {
        // Number overflow ("number overflow parsing '1e999'") has no position:
        // find the number in the text.
        std::string message = withoutExceptionId(e.what());
        const size_t open = message.find('\'');
        const size_t close = message.rfind('\'');
        if (open != std::string::npos && close > open) {
            const std::string token = message.substr(open + 1, close - open - 1);
            const size_t at = text.find(token);
            const std::string pointer = checker.currentPointer();
            message = (at != std::string::npos ? lineAndColumn(text, at) + ": " : std::string()) +
                      (pointer.empty() ? std::string() : pointer + ": ") + "number " + token +
                      " is out of range" + kBeyondDoubles;
        }
        return makeError(where, printable(message));
    } catch (const json::exception& e) {
        return makeError(where, printable(withoutExceptionId(e.what())));
    }
    if (!checker.duplicatePointer().empty()) {
        return makeError(where,
                         checker.duplicatePointer() + ": duplicate key " + quoteForMessage(checker.duplicateKey()));
    }
    return document;
}

std::string jsonPointerSegment(const std::string& key) {
    std::string out;
    out.reserve(key.size());
    for (const char c : key) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else if (byte < 0x20 || byte == 0x7f) {
            out += controlEscape(byte);
        } else {
            out += c;
        }
    }
    return out;
}

std::string quoteForMessage(const std::string& s) {
    std::string out = "\"";
    for (size_t i = 0; i < s.size() && i < kMaxQuotedChars; ++i) {
        const auto byte = static_cast<unsigned char>(s[i]);
        if (s[i] == '"' || s[i] == '\\') {
            out += '\\';
            out += s[i];
        } else if (byte < 0x20 || byte == 0x7f) {
            out += controlEscape(byte);
        } else {
            out += s[i];
        }
    }
    if (s.size() > kMaxQuotedChars) {
        out += "...";
    }
    return out + "\"";
}

std::string suggestionForMessage(const std::string& given, const std::vector<std::string>& known) {
    const std::string closest = closestName(given, known);
    return closest.empty() ? "" : ": did you mean " + quoteForMessage(closest) + "?";
}

std::string listForMessage(const std::vector<std::string>& items, const char* lastSeparator) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) {
            out += (i + 1 == items.size()) ? std::string(" ") + lastSeparator + " " : std::string(", ");
        }
        out += items[i];
    }
    return out;
}

std::string formatNumberForMessage(double x) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
    return std::string(buffer, result.ptr);
}

std::string formatNumberForMessage(float x) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
    return std::string(buffer, result.ptr);
}

std::string jsonTypeForMessage(const json& value) {
    switch (value.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return "a boolean";
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
        case json::value_t::number_float: return "a number";
        case json::value_t::string: return "a string";
        case json::value_t::array: return "an array";
        case json::value_t::object: return "an object";
        default: return "an unsupported value";
    }
}

bool Range::contains(double x) const {
    const bool aboveLow = lowOpen ? x > low : x >= low;
    const bool belowHigh = highOpen ? x < high : x <= high;
    return aboveLow && belowHigh;
}

std::string Range::describe() const {
    const bool hasLow = low > -1e299;
    const bool hasHigh = high < 1e299;
    if (hasLow && hasHigh) {
        return std::string("must be in ") + (lowOpen ? "(" : "[") + formatNumberForMessage(low) + ", " +
               formatNumberForMessage(high) + (highOpen ? ")" : "]");
    }
    if (hasLow) {
        return std::string("must be ") + (lowOpen ? "> " : ">= ") + formatNumberForMessage(low);
    }
    if (hasHigh) {
        return std::string("must be ") + (highOpen ? "< " : "<= ") + formatNumberForMessage(high);
    }
    return "must be a number";
}

void JsonContext::fail(const std::string& pointer, const std::string& problem) {
    if (!mError) {
        mError = Error{mWhere, pointer.empty() ? problem : pointer + ": " + problem};
    }
}

bool JsonContext::check(bool condition, const std::string& pointer, const std::string& problem) {
    if (!condition) {
        fail(pointer, problem);
    }
    return condition;
}

JsonObject::JsonObject(JsonContext& context, const json& value, std::string pointer,
                       const std::vector<std::string>& known)
    : mContext(context), mPointer(std::move(pointer)) {
    if (mContext.failed()) {
        return;
    }
    if (!value.is_object()) {
        mContext.fail(mPointer, "expected an object, got " + jsonTypeForMessage(value));
        return;
    }
    for (const auto& item : value.items()) {
        bool isKnown = false;
        for (const std::string& name : known) {
            isKnown = isKnown || item.key() == name;
        }
        if (!isKnown) {
            mContext.fail(
                mPointer + "/" + jsonPointerSegment(item.key()),
                "unknown key " + quoteForMessage(item.key()) + suggestionForMessage(item.key(), known) + " (known: " +
                    listForMessage(known, "and") + ")");
            return;
        }
    }
    mValue = &value;
}

bool JsonObject::has(const char* key) const {
    return member(key) != nullptr;
}

const json* JsonObject::member(const char* key) const {
    if (mValue == nullptr || mContext.failed()) {
        return nullptr;
    }
    const auto it = mValue->find(key);
    return it == mValue->end() ? nullptr : &*it;
}

void JsonObject::number(const char* key, float& out, const Range& range) {
    if (const json* value = member(key)) {
        readFloat(*value, pointer(key), range, out);
    }
}

bool JsonObject::readFloat(const json& value, const std::string& where, const Range& range, float& out) {
    if (!mContext.check(value.is_number(), where, "expected a number, got " + jsonTypeForMessage(value))) {
        return false;
    }
    const double x = value.get<double>();
    if (!mContext.check(std::isfinite(x) && std::fabs(x) <= double(std::numeric_limits<float>::max()), where,
                        "number " + formatNumberForMessage(x) + " is out of range for a 32-bit float")) {
        return false;
    }
    // Range-check the float that is stored, not the double that was written.
    // A value the range holds whose float rounds past a bound (1e20 is not a
    // float) is stored as the float next to it inside the range.
    auto f = static_cast<float>(x);
    if (range.contains(x) && !range.contains(double(f))) {
        // One float towards the written value, which lies inside.
        const float inward = std::nextafter(f, double(f) < x ? HUGE_VALF : -HUGE_VALF);
        if (range.contains(double(inward))) f = inward;
    }
    if (!range.contains(double(f))) {
        // A bound such as 1e20 is not a float: say why its own value is refused.
        char stored[48];
        std::snprintf(stored, sizeof stored, "%.9g", double(f));
        const std::string rounding =
            range.contains(x) ? std::string(" (") + stored + " as a 32-bit float)" : std::string();
        mContext.check(false, where, range.describe() + ", got " + formatNumberForMessage(x) + rounding);
        return false;
    }
    out = f;
    return true;
}

void JsonObject::integer(const char* key, int& out, const Range& range) {
    const json* value = member(key);
    if (value == nullptr) {
        return;
    }
    const std::string where = pointer(key);
    if (!mContext.check(value->is_number(), where, "expected an integer, got " + jsonTypeForMessage(*value))) {
        return;
    }
    // JSON has one number type: 1024.0 is the integer 1024, 1024.5 is not.
    const double x = value->get<double>();
    if (!mContext.check(std::isfinite(x) && std::floor(x) == x, where,
                        "expected an integer, got " + formatNumberForMessage(x)) ||
        !mContext.check(std::fabs(x) <= double(std::numeric_limits<int>::max()), where,
                        "integer " + formatNumberForMessage(x) + " is out of range")) {
        return;
    }
    if (mContext.check(range.contains(x), where, range.describe() + ", got " + formatNumberForMessage(x))) {
        out = static_cast<int>(x);
    }
}

void JsonObject::boolean(const char* key, bool& out) {
    const json* value = member(key);
    if (value == nullptr) {
        return;
    }
    if (mContext.check(value->is_boolean(), pointer(key),
                       "expected true or false, got " + jsonTypeForMessage(*value))) {
        out = value->get<bool>();
    }
}

void JsonObject::string(const char* key, std::string& out, bool allowEmpty) {
    const json* value = member(key);
    if (value == nullptr) {
        return;
    }
    const std::string where = pointer(key);
    if (!mContext.check(value->is_string(), where, "expected a string, got " + jsonTypeForMessage(*value))) {
        return;
    }
    const auto& text = value->get_ref<const std::string&>();
    if (mContext.check(allowEmpty || !text.empty(), where, "must not be empty")) {
        out = text;
    }
}

void JsonObject::vec3(const char* key, glm::vec3& out, const Range& range) {
    const json* value = member(key);
    if (value == nullptr) {
        return;
    }
    const std::string where = pointer(key);
    if (!mContext.check(value->is_array(), where,
                        "expected an array of 3 numbers, got " + jsonTypeForMessage(*value)) ||
        !mContext.check(value->size() == 3, where,
                        "expected an array of 3 numbers, got " + std::to_string(value->size()) + " elements")) {
        return;
    }
    glm::vec3 result = out;
    for (glm::length_t i = 0; i < 3; ++i) {
        if (!readFloat((*value)[static_cast<size_t>(i)], where + "/" + std::to_string(i), range, result[i])) {
            return;
        }
    }
    out = result;
}

void JsonObject::choice(const char* key, const char* noun, const std::vector<std::string>& options, int& out) {
    std::string text;
    string(key, text);
    if (!has(key)) {
        return;
    }
    for (size_t i = 0; i < options.size(); ++i) {
        if (text == options[i]) {
            out = static_cast<int>(i);
            return;
        }
    }
    mContext.fail(pointer(key), std::string("unknown ") + noun + " " + quoteForMessage(text) +
                                    suggestionForMessage(text, options) + " (expected " + listForMessage(options, "or") + ")");
}

const json* JsonObject::array(const char* key, size_t maxSize, const char* elementNoun) {
    const json* value = member(key);
    if (value == nullptr) {
        return nullptr;
    }
    const std::string where = pointer(key);
    if (!mContext.check(value->is_array(), where, "expected an array, got " + jsonTypeForMessage(*value)) ||
        !mContext.check(value->size() <= maxSize, where,
                        "too many " + std::string(elementNoun) + " (" + std::to_string(value->size()) + "; at most " +
                            std::to_string(maxSize) + ")")) {
        return nullptr;
    }
    return value;
}

}  // namespace dermis
