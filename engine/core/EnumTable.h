#pragma once
// One table per closed set (an enum): each value's name as files, `--set` and
// the command line spell it, and a one-line description for help texts. The
// scene loader and writer, the viewer's combo boxes, the bench and the CLI
// all take names from the table, so a new value is added in one place, and
// code that must visit every value loops over the table.

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dermis {

template <typename E>
struct EnumEntry {
    E value;
    std::string_view name;
    std::string_view description;
};

template <typename E, size_t N>
class EnumTable {
public:
    constexpr EnumTable(std::string_view noun, const std::array<EnumEntry<E>, N>& entries)
        : mNoun(noun), mEntries(entries) {}

    // What the set is called in messages: "SSS mode" in `unknown SSS mode "x"`.
    constexpr std::string_view noun() const { return mNoun; }
    constexpr size_t size() const { return N; }
    constexpr const EnumEntry<E>* begin() const { return mEntries.data(); }
    constexpr const EnumEntry<E>* end() const { return mEntries.data() + N; }

    std::optional<E> parse(std::string_view name) const {
        for (const EnumEntry<E>& entry : mEntries) {
            if (entry.name == name) return entry.value;
        }
        return std::nullopt;
    }
    // "?" for a value outside the table (a cast from a bad integer).
    constexpr std::string_view name(E value) const {
        for (const EnumEntry<E>& entry : mEntries) {
            if (entry.value == value) return entry.name;
        }
        return "?";
    }
    constexpr std::string_view description(E value) const {
        for (const EnumEntry<E>& entry : mEntries) {
            if (entry.value == value) return entry.description;
        }
        return "";
    }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const EnumEntry<E>& entry : mEntries) out.emplace_back(entry.name);
        return out;
    }
    std::vector<E> values() const {
        std::vector<E> out;
        for (const EnumEntry<E>& entry : mEntries) out.push_back(entry.value);
        return out;
    }
    // "ss|ts": for usage lines and errors.
    std::string list(std::string_view separator = "|") const {
        std::string out;
        for (const EnumEntry<E>& entry : mEntries) {
            if (!out.empty()) out += separator;
            out += entry.name;
        }
        return out;
    }
    // One "name  description" line per value, each starting with `indent`, the
    // descriptions aligned at `nameColumn` characters after the indent.
    std::string helpLines(std::string_view indent, size_t nameColumn = 20) const {
        std::string lines;
        for (const EnumEntry<E>& entry : mEntries) {
            std::string name(entry.name);
            name.resize(std::max(name.size() + 2, nameColumn), ' ');
            lines += std::string(indent) + name + std::string(entry.description) + '\n';
        }
        return lines;
    }
    // Every value appears once and every name once: for static_assert.
    constexpr bool isOneToOne() const {
        for (size_t i = 0; i < N; ++i) {
            for (size_t j = i + 1; j < N; ++j) {
                if (mEntries[i].value == mEntries[j].value || mEntries[i].name == mEntries[j].name) return false;
            }
        }
        return true;
    }

private:
    std::string_view mNoun;
    std::array<EnumEntry<E>, N> mEntries;
};

template <typename E, size_t N>
EnumTable(std::string_view, const std::array<EnumEntry<E>, N>&) -> EnumTable<E, N>;

}  // namespace dermis
