#pragma once
// Loading compressed glTF: the procedural head, subdivided past 100k
// triangles, as written plain and through gltfpack and draco_transcoder
// (GltfDecodeBenchmarks.cpp).

namespace dermis::bench {

// Prints the load times' table (after the run).
void printGltfDecodeSummary();

}  // namespace dermis::bench
