#include "QualityTableFiles.h"

#include "bench/QualityTune.h"

#include <filesystem>

namespace dermis::cli {

std::string markdownPath(const std::string& jsonPath) {
    std::filesystem::path path(jsonPath);
    path.replace_extension(".md");
    return path.string();
}

Status stageQualityTable(const std::string& json, const QualityTable& table, double margin, const std::string& outPath,
                         OutputFiles& outputs) {
    if (auto check = parseQualityTable(json, outPath); !check.ok()) return check.error();
    if (Status written = outputs.stageText(outPath, json); !written.ok()) return written;
    return outputs.stageText(markdownPath(outPath), bench::qualityTableMarkdown(table, margin));
}

}  // namespace dermis::cli
