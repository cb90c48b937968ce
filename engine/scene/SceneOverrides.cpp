#include "scene/SceneOverrides.h"

#include "scene/JsonReader.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <charconv>
#include <limits>

namespace dermis {

namespace {

using nlohmann::json;

// The keys of a scene document's root; any other first key is under settings.
const std::vector<std::string> kRootKeys = {"camera", "lights", "characters", "background", "environment",
                                                 "settings"};

bool isIndex(const std::string& key) {
    return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Out-of-range indices become SIZE_MAX, which no array reaches.
size_t parseIndex(const std::string& key) {
    size_t index = 0;
    const auto result = std::from_chars(key.data(), key.data() + key.size(), index);
    return result.ec == std::errc() ? index : std::numeric_limits<size_t>::max();
}

// "1e999", "-1e400": a number in JSON's grammar that no double holds (JSON
// parsing refuses it, and it must not fall back to being a string).
bool looksLikeOutOfRangeNumber(const std::string& text) {
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    const double parsed = std::strtod(text.c_str(), &end);
    const bool whole = end == text.c_str() + text.size();
    const bool numeric = text.find_first_not_of("+-0123456789.eE") == std::string::npos;
    return whole && numeric && (errno == ERANGE || !std::isfinite(parsed)) && std::fabs(parsed) > 1.0;
}

std::string elementCount(size_t n) {
    return std::to_string(n) + (n == 1 ? " element" : " elements");
}

std::vector<std::string> splitPath(const std::string& path) {
    std::vector<std::string> keys;
    size_t begin = 0;
    while (true) {
        const size_t dot = path.find('.', begin);
        keys.push_back(path.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin));
        if (dot == std::string::npos) {
            return keys;
        }
        begin = dot + 1;
    }
}

// Whether the error is about the value at `pointer` or inside it.
bool isAbout(const Error& error, const std::string& pointer) {
    const std::string& what = error.what;
    return what.size() > pointer.size() && what.compare(0, pointer.size(), pointer) == 0 &&
           (what[pointer.size()] == ':' || what[pointer.size()] == '/');
}

// Names the override that caused `error` (the result of reading `original`
// with every change applied), or keeps the file's name when the file alone
// has that error. An override whose value holds the offending value is the
// cause; otherwise (a check across keys such as near_m < far_m, or a key that
// an override created) the first override after which the error appears.
Error attributeError(const Error& error, const json& original, const std::vector<SceneOverride>& changes) {
    for (auto change = changes.rbegin(); change != changes.rend(); ++change) {
        if (isAbout(error, change->pointer())) {
            return Error{change->where(), error.what};
        }
    }
    json document = original;
    Result<Scene> partial = readSceneDocument(document, error.where);
    if (!partial.ok() && partial.error().what == error.what) {
        return error;
    }
    for (const SceneOverride& change : changes) {
        (void)applySceneOverride(document, change);  // succeeded before, on the same document
        partial = readSceneDocument(document, error.where);
        if (!partial.ok() && partial.error().what == error.what) {
            return Error{change.where(), error.what};
        }
    }
    return Error{changes.back().where(), error.what};
}

}  // namespace

std::string SceneOverride::where() const {
    std::string shown = text;
    for (char& c : shown) {
        const auto byte = static_cast<unsigned char>(c);
        c = (byte < 0x20 || byte == 0x7f) ? '?' : c;
    }
    return "--set " + shown;
}

std::string SceneOverride::pointer() const {
    std::string out;
    for (const std::string& key : path) {
        out += "/" + jsonPointerSegment(key);
    }
    return out;
}

Result<SceneOverride> parseSceneOverride(const std::string& text) {
    SceneOverride change;
    change.text = text;
    const size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0) {
        return makeError(change.where(), "expected PATH=VALUE");
    }
    const std::string path = text.substr(0, equals);
    change.path = splitPath(path);
    if (std::find(change.path.begin(), change.path.end(), std::string()) != change.path.end()) {
        return makeError(change.where(), "expected PATH=VALUE, with no empty key in PATH " + quoteForMessage(path));
    }
    if (std::find(kRootKeys.begin(), kRootKeys.end(), change.path.front()) == kRootKeys.end()) {
        change.path.insert(change.path.begin(), "settings");
    }
    const std::string valueText = text.substr(equals + 1);
    Result<json> value = parseJsonText(valueText, "");
    if (!value.ok() && looksLikeOutOfRangeNumber(valueText)) {
        // As the file's number would be named: the key, then the number (no double holds it).
        return makeError(change.where(), change.pointer() + ": number " + valueText + " is out of range" + kBeyondDoubles);
    }
    // An array or object that does not parse (a syntax error, or nested
    // deeper than the limit) was meant as JSON: refuse it rather than read it
    // as a string.
    const size_t first = valueText.find_first_not_of(" \t");
    if (!value.ok() && first != std::string::npos && (valueText[first] == '[' || valueText[first] == '{')) {
        return makeError(change.where(), "the value is not valid JSON: " + value.error().what);
    }
    change.value = value.ok() ? std::move(*value) : json(valueText);
    return change;
}

Status applySceneOverride(json& document, const SceneOverride& change) {
    const auto fail = [&change](const std::string& pointer, const std::string& problem) {
        return makeError(change.where(), pointer.empty() ? problem : pointer + ": " + problem);
    };
    json* node = &document;
    std::string pointer;
    for (size_t i = 0; i < change.path.size(); ++i) {
        const std::string& key = change.path[i];
        const bool last = i + 1 == change.path.size();
        const std::string child = pointer + "/" + jsonPointerSegment(key);
        if (node->is_object()) {
            if (last) {
                (*node)[key] = change.value;
                return success();
            }
            auto it = node->find(key);
            if (it == node->end()) {
                const std::string& next = change.path[i + 1];
                if (isIndex(next)) {
                    return fail(child + "/" + next, "no such array element (" + child + " is absent)");
                }
                it = node->emplace(key, json::object()).first;
            }
            node = &*it;
        } else if (node->is_array()) {
            if (!isIndex(key)) {
                return fail(pointer, "expected an array index, got " + quoteForMessage(key));
            }
            const size_t index = parseIndex(key);
            if (index >= node->size()) {
                return fail(child, "no such array element (" + pointer + " has " + elementCount(node->size()) + ")");
            }
            if (last) {
                (*node)[index] = change.value;
                return success();
            }
            node = &(*node)[index];
        } else {
            return fail(pointer, "cannot set " + quoteForMessage(key) + " inside " + jsonTypeForMessage(*node));
        }
        pointer = child;
    }
    return success();
}

Result<Scene> parseSceneWithOverrides(const std::string& jsonText, const std::string& pathForMessages,
                                      const std::vector<std::string>& overrides) {
    std::vector<SceneOverride> changes;
    for (const std::string& text : overrides) {
        Result<SceneOverride> change = parseSceneOverride(text);
        if (!change) {
            return change.error();
        }
        changes.push_back(std::move(*change));
    }
    Result<json> original = parseJsonText(jsonText, pathForMessages);
    if (!original) {
        return original.error();
    }
    // A file that is not an object is the file's error, whatever the overrides.
    if (changes.empty() || !original->is_object()) {
        return readSceneDocument(*original, pathForMessages);
    }
    json document = *original;
    for (const SceneOverride& change : changes) {
        const Status applied = applySceneOverride(document, change);
        if (!applied) {
            return applied.error();
        }
    }
    Result<Scene> scene = readSceneDocument(document, pathForMessages);
    if (!scene) {
        return attributeError(scene.error(), *original, changes);
    }
    return scene;
}

}  // namespace dermis
