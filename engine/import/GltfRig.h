#pragma once
// The part of a glTF file that moves vertices, read into a Rig (anim/Rig.h):
// the node hierarchy with each node's rest transform, skins (glTF 2.0
// §3.7.3), animation clips (§3.11) and morph targets (§3.7.2.2).
//
// When a file has any of them, the loader keeps every primitive's vertices as
// the file gives them (no node transform applied) and addPrimitive records
// what moves each vertex: a skinned primitive its four joints and weights, any
// other its mesh node (weight 1). finish() then poses the rest pose into the
// model's mesh, so a model with a rig looks, unanimated, as its file does.
//
// What is refused, with file and place named: joints outside their skin,
// negative or non-finite weights, weights summing to zero, a skinned node's
// primitive without JOINTS_0/WEIGHTS_0, channels targeting missing nodes or a
// node given as a matrix, a weights channel on a node without morph targets,
// keyframe times that do not increase, outputs of the wrong size. Weights
// whose sum is off one by more than kWeightSumTolerance are normalised with
// one warning; a second influence set (JOINTS_1/WEIGHTS_1) keeps the four
// largest of the eight, renormalised, with one warning giving the largest
// weight dropped.

#include "anim/Rig.h"
#include "core/Result.h"
#include "import/GltfAccessors.h"
#include "mesh/Model.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace dermis {

// glTF asks weights to sum to one "as close as reasonably possible"; 8-bit
// normalised weights are off by up to 4 steps of 1/255.
inline constexpr float kWeightSumTolerance = 2e-2f;

// A node's rest transform (glTF 2.0 §3.5.3): TRS, or the matrix it is given
// as; sizes and finiteness checked.
Result<NodeTransform> readNodeTransform(const tinygltf::Node& node, int index, const std::string& path);

// The scene's limit on a character's scale holds whatever the source: each
// axis of a composed node, joint or inverse-bind transform (its 3x3 columns'
// lengths) must lie in [kMinMetresPerMeshUnit, kMaxMetresPerMeshUnit], as
// must an animated scale; exactly 0 (how exporters hide a part) is allowed.
// `where` names the node ("node 3 'Armature'").
Status checkTransformScale(const glm::mat3& linear, const std::string& path, const std::string& where);

class GltfRigBuilder {
public:
    GltfRigBuilder(const tinygltf::Model& gltf, const GltfAccessors& accessors, std::string path)
        : mGltf(gltf), mAccessors(accessors), mPath(std::move(path)) {}

    // Whether the file has skins, clips or morph targets.
    static bool wanted(const tinygltf::Model& gltf);

    // Nodes, skins and clips.
    Status readHierarchy();
    // Whether a vertex of mesh node `node` in its rest pose is mirrored (its
    // triangles' winding must be flipped as the static loader does).
    bool mirroredAtRest(int node) const;
    // A primitive of mesh node `node` whose vertexCount vertices were just
    // appended to the model's mesh at firstVertex.
    Status addPrimitive(int node, const tinygltf::Primitive& primitive, size_t firstVertex, size_t vertexCount,
                        const std::string& where);
    // The vertices from firstVertex on, just added, become copies of them:
    // vertex firstVertex + i copies firstVertex + source[i] (a primitive drawn
    // flat, with a vertex per triangle corner: mesh/FlatNormals.h).
    Status copyVertices(size_t firstVertex, const std::vector<uint32_t>& source);
    // Keeps the mesh's vertices as the bind vertices and poses the rest pose into it.
    Rig finish(MeshData& mesh);

private:
    Error fail(const std::string& what) const { return makeError(mPath, what); }
    Status readNodes();
    Status readSkins();
    Status readClips();
    Result<AnimationChannel> readChannel(const tinygltf::Animation& animation, size_t channel, const std::string& where);
    Status readInfluences(int skin, const tinygltf::Primitive& primitive, size_t vertexCount, const std::string& where);
    Status readMorphTargets(int node, const tinygltf::Primitive& primitive, size_t firstVertex, size_t vertexCount,
                            const std::string& where);
    size_t rigidEntry(int node);

    const tinygltf::Model& mGltf;
    const GltfAccessors& mAccessors;
    std::string mPath;
    Rig mRig;
    std::vector<size_t> mSkinPaletteOffset;   // per skin
    std::vector<int> mRigidEntryOfNode;       // per node, -1 until used
    std::vector<int> mFirstSlotOfNode;        // per node, -1 until its targets get slots
    std::vector<glm::mat4> mRestWorld;        // per node
    size_t mRenormalised = 0;
    float mWorstSum = 1.0f;
    size_t mTruncated = 0;
    float mLargestDropped = 0.0f;
};

}  // namespace dermis
