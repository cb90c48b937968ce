#include "import/GltfRig.h"

#include "core/Limits.h"
#include "core/Log.h"

#include <cstdio>

#include <algorithm>
#include <cmath>

namespace dermis {
namespace {

std::string clipName(const tinygltf::Animation& animation, size_t index) {
    return animation.name.empty() ? "animation" + std::to_string(index) : animation.name;
}

bool finiteMatrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

Result<NodeTransform> readNodeTransform(const tinygltf::Node& node, int index, const std::string& path) {
    const std::string where = "node " + std::to_string(index);
    NodeTransform transform;
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16)
            return makeError(path, where + ": matrix has " + std::to_string(node.matrix.size()) + " values, not 16");
        transform.hasFixedMatrix = true;
        for (int i = 0; i < 16; ++i)
            transform.fixedMatrix[i / 4][i % 4] = static_cast<float>(node.matrix[static_cast<size_t>(i)]);
    } else {
        if (!node.translation.empty() && node.translation.size() != 3)
            return makeError(path, where + ": translation needs 3 values");
        if (!node.rotation.empty() && node.rotation.size() != 4) return makeError(path, where + ": rotation needs 4 values");
        if (!node.scale.empty() && node.scale.size() != 3) return makeError(path, where + ": scale needs 3 values");
        for (int i = 0; i < 3 && !node.translation.empty(); ++i)
            transform.translation[i] = static_cast<float>(node.translation[static_cast<size_t>(i)]);
        for (int i = 0; i < 3 && !node.scale.empty(); ++i)
            transform.scale[i] = static_cast<float>(node.scale[static_cast<size_t>(i)]);
        if (!node.rotation.empty()) {
            // glTF stores x, y, z, w; glm::quat's constructor takes w first.
            glm::quat rotation(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                               static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
            const float length = glm::length(rotation);
            if (!(length > 0.0f) || !std::isfinite(length))
                return makeError(path, where + ": rotation is not a valid quaternion");
            transform.rotation = rotation / length;
        }
    }
    if (!finiteMatrix(transform.matrix())) return makeError(path, where + ": transform is not finite");
    return transform;
}

Status checkTransformScale(const glm::mat3& linear, const std::string& path, const std::string& where) {
    for (int axis = 0; axis < 3; ++axis) {
        const double scale = glm::length(glm::dvec3(linear[axis]));
        // Exactly 0 is how exporters hide a part: it collapses, finitely.
        if (scale == 0.0 || (std::isfinite(scale) && scale >= kMinMetresPerMeshUnit && scale <= kMaxMetresPerMeshUnit))
            continue;
        char line[200];
        std::snprintf(line, sizeof line, "%s: its composed scale %.3g (axis %c) is outside [%g, %g], the limit of a "
                      "character's scale", where.c_str(), scale, "xyz"[axis], kMinMetresPerMeshUnit, kMaxMetresPerMeshUnit);
        return makeError(path, line);
    }
    return success();
}

bool GltfRigBuilder::wanted(const tinygltf::Model& gltf) {
    if (!gltf.skins.empty() || !gltf.animations.empty()) return true;
    for (const tinygltf::Mesh& mesh : gltf.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives)
            if (!primitive.targets.empty()) return true;
    return false;
}

Status GltfRigBuilder::readHierarchy() {
    if (Status status = readNodes(); !status) return status;
    if (Status status = readSkins(); !status) return status;
    return readClips();
}

Status GltfRigBuilder::readNodes() {
    const size_t count = mGltf.nodes.size();
    mRig.nodes.resize(count);
    mRigidEntryOfNode.assign(count, -1);
    mFirstSlotOfNode.assign(count, -1);
    for (size_t i = 0; i < count; ++i) {
        const tinygltf::Node& node = mGltf.nodes[i];
        Result<NodeTransform> rest = readNodeTransform(node, static_cast<int>(i), mPath);
        if (!rest) return rest.error();
        SkeletonNode& out = mRig.nodes[i];
        out.name = node.name;
        out.rest = std::move(rest.value());
        std::vector<double> weights = node.weights;
        if (weights.empty() && node.mesh >= 0 && static_cast<size_t>(node.mesh) < mGltf.meshes.size())
            weights = mGltf.meshes[static_cast<size_t>(node.mesh)].weights;
        for (double w : weights) out.rest.weights.push_back(static_cast<float>(w));
        for (int child : node.children) {
            if (child < 0 || static_cast<size_t>(child) >= count)
                return fail("node " + std::to_string(i) + ": child " + std::to_string(child) + " is out of range (" +
                            std::to_string(count) + " nodes)");
            if (mRig.nodes[static_cast<size_t>(child)].parent >= 0)
                return fail("node " + std::to_string(child) + " has two parents");
            mRig.nodes[static_cast<size_t>(child)].parent = static_cast<int>(i);
        }
    }
    mRestWorld = worldFromNodes(mRig.nodes, restPose(mRig.nodes));
    for (size_t i = 0; i < mRestWorld.size(); ++i) {
        const std::string& name = mRig.nodes[i].name;
        if (Status checked = checkTransformScale(glm::mat3(mRestWorld[i]), mPath,
                                                 "node " + std::to_string(i) + (name.empty() ? "" : " '" + name + "'"));
            !checked)
            return checked;
    }
    return success();
}

Status GltfRigBuilder::readSkins() {
    for (size_t s = 0; s < mGltf.skins.size(); ++s) {
        const tinygltf::Skin& skin = mGltf.skins[s];
        const std::string where = "skin " + std::to_string(s) + (skin.name.empty() ? "" : " '" + skin.name + "'");
        Skin out;
        out.name = skin.name;
        for (int joint : skin.joints) {
            if (joint < 0 || static_cast<size_t>(joint) >= mGltf.nodes.size())
                return fail(where + ": joint node " + std::to_string(joint) + " is out of range (" +
                            std::to_string(mGltf.nodes.size()) + " nodes)");
            out.joints.push_back(joint);
        }
        if (out.joints.empty()) return fail(where + " has no joints");
        out.inverseBindMatrices.assign(out.joints.size(), glm::mat4(1.0f));  // §3.7.3: identity when absent
        if (skin.inverseBindMatrices >= 0) {
            Result<std::vector<float>> values =
                mAccessors.readFloats(skin.inverseBindMatrices, TINYGLTF_TYPE_MAT4, where + " inverseBindMatrices");
            if (!values) return values.error();
            if (values->size() < 16 * out.joints.size())
                return fail(where + ": " + std::to_string(values->size() / 16) + " inverse bind matrices for " +
                            std::to_string(out.joints.size()) + " joints");
            for (size_t j = 0; j < out.joints.size(); ++j) {
                for (int i = 0; i < 16; ++i) out.inverseBindMatrices[j][i / 4][i % 4] = (*values)[16 * j + static_cast<size_t>(i)];
                if (Status checked = checkTransformScale(glm::mat3(out.inverseBindMatrices[j]), mPath,
                                                         where + " inverse bind matrix " + std::to_string(j));
                    !checked)
                    return checked;
            }
        }
        mSkinPaletteOffset.push_back(mRig.palette.size());
        for (size_t j = 0; j < out.joints.size(); ++j)
            mRig.palette.push_back({out.joints[j], static_cast<int>(s), static_cast<int>(j)});
        mRig.skins.push_back(std::move(out));
    }
    if (mRig.palette.size() > kMaxPaletteEntries)
        return fail(std::to_string(mRig.palette.size()) + " joints in all; at most " + std::to_string(kMaxPaletteEntries));
    return success();
}

Result<AnimationChannel> GltfRigBuilder::readChannel(const tinygltf::Animation& animation, size_t index,
                                                     const std::string& where) {
    const tinygltf::AnimationChannel& channel = animation.channels[index];
    const std::string at = where + " channel " + std::to_string(index);
    AnimationChannel out;
    if (channel.target_node < 0 || static_cast<size_t>(channel.target_node) >= mGltf.nodes.size())
        return fail(at + " targets node " + std::to_string(channel.target_node) + ", which does not exist (" +
                    std::to_string(mGltf.nodes.size()) + " nodes)");
    out.node = channel.target_node;
    const SkeletonNode& node = mRig.nodes[static_cast<size_t>(out.node)];
    auto property = kAnimatedProperties.parse(channel.target_path);
    if (!property) return fail(at + ": target path '" + channel.target_path + "' is not supported");
    out.property = *property;
    if (node.rest.hasFixedMatrix)
        return fail(at + " animates node " + std::to_string(out.node) + ", which is given as a matrix (glTF 2.0 §3.11 allows TRS only)");
    const tinygltf::Node& target = mGltf.nodes[static_cast<size_t>(out.node)];
    int type = TINYGLTF_TYPE_VEC3;
    out.components = 3;
    if (out.property == AnimatedProperty::Rotation) {
        type = TINYGLTF_TYPE_VEC4;
        out.components = 4;
    } else if (out.property == AnimatedProperty::Weights) {
        size_t targets = 0;
        if (target.mesh >= 0 && static_cast<size_t>(target.mesh) < mGltf.meshes.size())
            for (const tinygltf::Primitive& p : mGltf.meshes[static_cast<size_t>(target.mesh)].primitives)
                targets = std::max(targets, p.targets.size());
        if (targets == 0) return fail(at + " animates the morph weights of node " + std::to_string(out.node) + ", which has no morph targets");
        type = TINYGLTF_TYPE_SCALAR;
        out.components = static_cast<int>(targets);
    }
    if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= animation.samplers.size())
        return fail(at + ": sampler " + std::to_string(channel.sampler) + " is out of range");
    const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
    auto interpolation = kInterpolations.parse(sampler.interpolation.empty() ? "LINEAR" : sampler.interpolation);
    if (!interpolation) return fail(at + ": interpolation '" + sampler.interpolation + "' is not STEP, LINEAR or CUBICSPLINE");
    out.interpolation = *interpolation;
    Result<std::vector<float>> times = mAccessors.readFloats(sampler.input, TINYGLTF_TYPE_SCALAR, at + " input");
    if (!times) return times.error();
    if (times->empty()) return fail(at + " has no keyframes");
    for (size_t k = 1; k < times->size(); ++k)
        if (!((*times)[k] > (*times)[k - 1]))
            return fail(at + ": keyframe time " + std::to_string(k) + " (" + std::to_string((*times)[k]) +
                        " s) does not increase");
    Result<std::vector<float>> values = mAccessors.readFloats(sampler.output, type, at + " output");
    if (!values) return values.error();
    const size_t perKey = static_cast<size_t>(out.components) * (out.interpolation == Interpolation::CubicSpline ? 3 : 1);
    if (values->size() != times->size() * perKey)
        return fail(at + " output has " + std::to_string(values->size()) + " values, expected " +
                    std::to_string(times->size() * perKey) + " (" + std::to_string(times->size()) + " keyframes of " +
                    std::to_string(perKey) + ")");
    out.timesS = std::move(times.value());
    out.values = std::move(values.value());
    if (out.property == AnimatedProperty::Scale) {
        // CUBICSPLINE keys are (in-tangent, value, out-tangent): only the values are scales.
        const bool cubic = out.interpolation == Interpolation::CubicSpline;
        for (size_t v = cubic ? 3 : 0; v + 2 < out.values.size(); v += cubic ? 9 : 3) {
            const glm::mat3 scale(glm::vec3(out.values[v], 0, 0), glm::vec3(0, out.values[v + 1], 0),
                                  glm::vec3(0, 0, out.values[v + 2]));
            if (Status checked = checkTransformScale(scale, mPath, at + " key " + std::to_string(v / (cubic ? 9 : 3)));
                !checked)
                return checked.error();
        }
    }
    return out;
}

Status GltfRigBuilder::readClips() {
    for (size_t a = 0; a < mGltf.animations.size(); ++a) {
        const tinygltf::Animation& animation = mGltf.animations[a];
        AnimationClip clip;
        clip.name = clipName(animation, a);
        if (mRig.findClip(clip.name) >= 0) clip.name += " (" + std::to_string(a) + ")";
        const std::string where = "animation " + std::to_string(a) + " '" + clip.name + "'";
        for (size_t c = 0; c < animation.channels.size(); ++c) {
            Result<AnimationChannel> channel = readChannel(animation, c, where);
            if (!channel) return channel.error();
            clip.channels.push_back(std::move(channel.value()));
        }
        mRig.clips.push_back(std::move(clip));
    }
    return success();
}

bool GltfRigBuilder::mirroredAtRest(int node) const {
    const tinygltf::Node& n = mGltf.nodes[static_cast<size_t>(node)];
    return n.skin < 0 && glm::determinant(glm::mat3(mRestWorld[static_cast<size_t>(node)])) < 0.0f;
}

size_t GltfRigBuilder::rigidEntry(int node) {
    int& entry = mRigidEntryOfNode[static_cast<size_t>(node)];
    if (entry < 0) {
        entry = static_cast<int>(mRig.palette.size());
        mRig.palette.push_back({node, -1, 0});
    }
    return static_cast<size_t>(entry);
}

Status GltfRigBuilder::addPrimitive(int node, const tinygltf::Primitive& primitive, size_t firstVertex,
                                    size_t vertexCount, const std::string& where) {
    const int skin = mGltf.nodes[static_cast<size_t>(node)].skin;
    mRig.influences.resize(firstVertex);
    if (skin >= 0) {
        if (static_cast<size_t>(skin) >= mRig.skins.size())
            return fail("node " + std::to_string(node) + ": skin " + std::to_string(skin) + " is out of range");
        if (Status status = readInfluences(skin, primitive, vertexCount, where); !status) return status;
    } else {
        if (mRig.palette.size() >= kMaxPaletteEntries)
            return fail("more than " + std::to_string(kMaxPaletteEntries) + " joints and moving mesh nodes in all");
        SkinInfluence rigid;
        rigid.joints = glm::u16vec4(static_cast<uint16_t>(rigidEntry(node)), 0, 0, 0);
        rigid.weights = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
        mRig.influences.insert(mRig.influences.end(), vertexCount, rigid);
    }
    return readMorphTargets(node, primitive, firstVertex, vertexCount, where);
}

Status GltfRigBuilder::readInfluences(int skin, const tinygltf::Primitive& primitive, size_t vertexCount,
                                      const std::string& where) {
    std::vector<std::vector<float>> joints, weights;
    for (int set = 0; set < 2; ++set) {
        auto jointsIt = primitive.attributes.find("JOINTS_" + std::to_string(set));
        auto weightsIt = primitive.attributes.find("WEIGHTS_" + std::to_string(set));
        if (jointsIt == primitive.attributes.end() && weightsIt == primitive.attributes.end()) break;
        if (jointsIt == primitive.attributes.end() || weightsIt == primitive.attributes.end())
            return fail(where + ": JOINTS_" + std::to_string(set) + " and WEIGHTS_" + std::to_string(set) + " must come together");
        const tinygltf::Accessor& jointAccessor = mGltf.accessors[static_cast<size_t>(std::max(jointsIt->second, 0))];
        if (jointAccessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            jointAccessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
            return fail(where + ": JOINTS_" + std::to_string(set) + " must hold unsigned 8- or 16-bit integers");
        Result<std::vector<float>> j = mAccessors.readFloats(jointsIt->second, TINYGLTF_TYPE_VEC4, where + " JOINTS_" + std::to_string(set));
        if (!j) return j.error();
        Result<std::vector<float>> w = mAccessors.readFloats(weightsIt->second, TINYGLTF_TYPE_VEC4, where + " WEIGHTS_" + std::to_string(set));
        if (!w) return w.error();
        if (j->size() != 4 * vertexCount || w->size() != 4 * vertexCount)
            return fail(where + ": JOINTS_" + std::to_string(set) + "/WEIGHTS_" + std::to_string(set) +
                        " do not have one element per vertex (" + std::to_string(vertexCount) + ")");
        joints.push_back(std::move(j.value()));
        weights.push_back(std::move(w.value()));
    }
    if (joints.empty())
        return fail(where + ": its node has skin " + std::to_string(skin) + " but the primitive has no JOINTS_0/WEIGHTS_0");
    if (primitive.attributes.count("JOINTS_2"))
        return fail(where + ": more than two influence sets (JOINTS_2); at most 8 influences are supported");

    const size_t jointCount = mRig.skins[static_cast<size_t>(skin)].joints.size();
    const size_t offset = mSkinPaletteOffset[static_cast<size_t>(skin)];
    for (size_t v = 0; v < vertexCount; ++v) {
        std::vector<std::pair<float, size_t>> all;  // (weight, joint)
        for (size_t set = 0; set < joints.size(); ++set) {
            for (size_t i = 0; i < 4; ++i) {
                const float w = weights[set][4 * v + i];
                const auto joint = static_cast<size_t>(joints[set][4 * v + i]);
                if (!(w >= 0.0f))
                    return fail(where + ": WEIGHTS_" + std::to_string(set) + " of vertex " + std::to_string(v) + " is negative");
                if (w > 0.0f && joint >= jointCount)
                    return fail(where + ": JOINTS_" + std::to_string(set) + " of vertex " + std::to_string(v) + " names joint " +
                                std::to_string(joint) + "; skin " + std::to_string(skin) + " has " + std::to_string(jointCount) +
                                " joints");
                if (w > 0.0f) all.emplace_back(w, joint);
            }
        }
        std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        const bool truncated = all.size() > 4;
        if (truncated) {
            ++mTruncated;
            mLargestDropped = std::max(mLargestDropped, all[4].first);
            all.resize(4);
        }
        float sum = 0.0f;
        for (const auto& [w, joint] : all) sum += w;
        if (!(sum > 0.0f)) return fail(where + ": the weights of vertex " + std::to_string(v) + " sum to 0");
        if (std::abs(sum - 1.0f) > kWeightSumTolerance && !truncated) {
            ++mRenormalised;
            if (std::abs(sum - 1.0f) > std::abs(mWorstSum - 1.0f)) mWorstSum = sum;
        }
        SkinInfluence influence;
        for (size_t i = 0; i < all.size(); ++i) {
            influence.joints[static_cast<int>(i)] = static_cast<uint16_t>(offset + all[i].second);
            influence.weights[static_cast<int>(i)] = all[i].first / sum;
        }
        mRig.influences.push_back(influence);
    }
    return success();
}

Status GltfRigBuilder::readMorphTargets(int node, const tinygltf::Primitive& primitive, size_t firstVertex,
                                        size_t vertexCount, const std::string& where) {
    if (primitive.targets.empty()) return success();
    int& first = mFirstSlotOfNode[static_cast<size_t>(node)];
    if (first < 0) {
        first = static_cast<int>(mRig.morphSlots.size());
        for (size_t t = 0; t < primitive.targets.size(); ++t) mRig.morphSlots.push_back({node, static_cast<int>(t)});
        mRig.morphTargets.resize(mRig.morphSlots.size());
        if (mRig.morphSlots.size() > kMaxMorphSlots)
            return fail(std::to_string(mRig.morphSlots.size()) + " morph targets in all; at most " + std::to_string(kMaxMorphSlots));
    }
    const auto slots = static_cast<size_t>(std::count_if(mRig.morphSlots.begin(), mRig.morphSlots.end(),
                                                         [&](const MorphSlot& slot) { return slot.node == node; }));
    if (primitive.targets.size() != slots)
        return fail(where + ": " + std::to_string(primitive.targets.size()) + " morph targets, unlike the mesh's other primitives");
    if (mRig.morphSlots.size() * (firstVertex + vertexCount) > kMaxMorphDeltas)
        return fail("morph targets x vertices exceeds " + std::to_string(kMaxMorphDeltas));
    for (size_t t = 0; t < primitive.targets.size(); ++t) {
        MorphTarget& target = mRig.morphTargets[static_cast<size_t>(first) + t];
        struct Attribute {
            const char* name;
            std::vector<glm::vec3>* out;
        };
        for (const Attribute& attribute : {Attribute{"POSITION", &target.positions}, Attribute{"NORMAL", &target.normals},
                                           Attribute{"TANGENT", &target.tangents}}) {
            auto it = primitive.targets[t].find(attribute.name);
            if (it == primitive.targets[t].end()) continue;
            const std::string at = where + " target " + std::to_string(t) + " " + attribute.name;
            Result<std::vector<float>> values = mAccessors.readFloats(it->second, TINYGLTF_TYPE_VEC3, at);
            if (!values) return values.error();
            if (values->size() != 3 * vertexCount)
                return fail(at + " has " + std::to_string(values->size() / 3) + " elements, POSITION has " + std::to_string(vertexCount));
            attribute.out->resize(firstVertex, glm::vec3(0.0f));
            for (size_t v = 0; v < vertexCount; ++v)
                attribute.out->push_back(glm::vec3((*values)[3 * v], (*values)[3 * v + 1], (*values)[3 * v + 2]));
        }
    }
    return success();
}

Status GltfRigBuilder::copyVertices(size_t firstVertex, const std::vector<uint32_t>& source) {
    if (mRig.morphSlots.size() * (firstVertex + source.size()) > kMaxMorphDeltas)
        return fail("morph targets x vertices exceeds " + std::to_string(kMaxMorphDeltas) +
                    " once the primitives without normals have a vertex per triangle corner");
    auto copyTail = [&](auto& values) {
        if (values.size() <= firstVertex) return;  // nothing of this primitive's (a morph attribute it lacks)
        auto tail = values;
        tail.erase(tail.begin(), tail.begin() + std::ptrdiff_t(firstVertex));
        values.resize(firstVertex);
        for (uint32_t index : source) values.push_back(tail[index]);
    };
    copyTail(mRig.influences);
    for (MorphTarget& target : mRig.morphTargets)
        for (std::vector<glm::vec3>* attribute : {&target.positions, &target.normals, &target.tangents}) copyTail(*attribute);
    return success();
}

Rig GltfRigBuilder::finish(MeshData& mesh) {
    if (mRenormalised > 0)
        log::warn(mPath + ": the skin weights of " + std::to_string(mRenormalised) + " vertices do not sum to one (worst " +
                  std::to_string(mWorstSum) + "); normalised");
    if (mTruncated > 0)
        log::warn(mPath + ": " + std::to_string(mTruncated) + " vertices have more than 4 influences (JOINTS_1); the 4 largest are kept, "
                  "renormalised (largest weight dropped " + std::to_string(mLargestDropped) + ")");
    const size_t count = mesh.vertices.size();
    mRig.influences.resize(count);
    for (MorphTarget& target : mRig.morphTargets)
        for (std::vector<glm::vec3>* attribute : {&target.positions, &target.normals, &target.tangents})
            if (!attribute->empty()) attribute->resize(count, glm::vec3(0.0f));
    mRig.bind.positions.reserve(count);
    for (const Vertex& v : mesh.vertices) {
        mRig.bind.positions.push_back(v.position);
        mRig.bind.normals.push_back(v.normal);
        mRig.bind.tangents.push_back(v.tangent);
    }
    mRig.computeEntryBounds();
    setVertexFrames(mesh, deformRig(mRig, poseRig(mRig, -1, 0.0f)));
    return std::move(mRig);
}

}  // namespace dermis
