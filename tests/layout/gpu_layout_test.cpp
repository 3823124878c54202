// The C++ mirrors of the shader's blocks (host/layout/gpu_layout.h) against the GLSL itself: every
// member's offset and every array's stride as glslang's reflection lays the blocks out, in float
// and double, as storage buffers (std430) and as the small-scene uniform buffers (std140). A
// member added on one side only fails here, with no device.

#include <algorithm>
#include <cstddef>
#include <map>
#include <ostream>
#include <regex>
#include <string>
#include <vector>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

#include "kernels/shader_library_includer.h"
#include "layout/gpu_layout.h"

namespace hexray {
namespace {

using namespace gpu;

struct Member {
    std::string name;  // as glslang's reflection names it
    std::size_t offset;
};

#define MEMBER(prefix, type, member)           \
    Member {                                   \
        prefix #member, offsetof(type, member) \
    }

// `nodes`, `looks` and `lights` name the arrays whose element 0 reflection lists: the uniform blocks
// (where the looks follow SMALL_SCENE_CAPACITY nodes in the node block: `looksStart` bytes in), or
// for the texel layout (read as texels at the offsets gpu_layout.h asserts) the std430 probes.
template <typename Real>
std::vector<Member> sceneMembers(const std::string& nodes, const std::string& looks, std::size_t looksStart,
                                 const std::string& lights) {
    using Frame = GpuFrame<Real>;
    using Node = GpuNode<Real>;
    using Look = GpuLook<Real>;
    using Light = GpuLight<Real>;
    const auto lookMember = [&](const char* name, std::size_t offset) {
        return Member{looks + "[0]." + name, looksStart + offset};
    };
    return {
        MEMBER("FrameBlock.", Frame, origin),
        MEMBER("FrameBlock.", Frame, sheetTopLeft),
        MEMBER("FrameBlock.", Frame, sheetRight),
        MEMBER("FrameBlock.", Frame, sheetDown),
        MEMBER("FrameBlock.", Frame, background),
        MEMBER("FrameBlock.", Frame, ambient),
        MEMBER("FrameBlock.", Frame, imageSize),
        MEMBER("FrameBlock.", Frame, samplingOffset),
        MEMBER("FrameBlock.", Frame, nodeCount),
        MEMBER("FrameBlock.", Frame, lightCount),
        MEMBER("FrameBlock.", Frame, planeCount),
        MEMBER(nodes + "[0].", Node, geometry),
        MEMBER(nodes + "[0].", Node, eyePower),
        MEMBER(nodes + "[0].", Node, geometryKind),
        MEMBER(nodes + "[0].", Node, look),
        lookMember("checker", offsetof(Look, checker)),
        lookMember("color1", offsetof(Look, color1)),
        lookMember("color2", offsetof(Look, color2)),
        lookMember("shaderKind", offsetof(Look, shaderKind)),
        MEMBER(lights + "[0].", Light, position),
        MEMBER(lights + "[0].", Light, power),
    };
}

template <typename Real>
std::vector<Member> outputMembers() {
    using Header = GpuTraceHeader<Real>;
    using Entry = GpuTraceEntry<Real>;
    return {
        MEMBER("BandBlock.", GpuBand, firstRow),
        MEMBER("BandBlock.", GpuBand, rowCount),
        MEMBER("BandBlock.", GpuBand, firstTile),
        MEMBER("BandBlock.", GpuBand, firstSample),
        MEMBER("BandBlock.", GpuBand, endSample),
        MEMBER("BandBlock.", GpuBand, firstLight),
        MEMBER("BandBlock.", GpuBand, endLight),
        MEMBER("carry[0].", GpuPixelCarry, sum),
        MEMBER("carry[0].", GpuPixelCarry, flags),
        MEMBER("carry[0].", GpuPixelCarry, irradiance),
        MEMBER("TraceBlock.header.", Header, request),
        MEMBER("TraceBlock.header.", Header, result),
        MEMBER("TraceBlock.header.", Header, rayOrigin),
        MEMBER("TraceBlock.header.", Header, rayDirection),
        MEMBER("TraceBlock.header.", Header, hitPosition),
        MEMBER("TraceBlock.header.", Header, hitNormal),
        MEMBER("TraceBlock.header.", Header, shadowOrigin),
        MEMBER("TraceBlock.header.", Header, albedo),
        MEMBER("TraceBlock.header.", Header, sampleColor),
        MEMBER("TraceBlock.header.", Header, pixelColor),
        // The entries follow the header: their offsets count from the block's start.
        Member{"TraceBlock.entries[0].values", sizeof(Header) + offsetof(Entry, values)},
        Member{"TraceBlock.entries[0].color", sizeof(Header) + offsetof(Entry, color)},
        Member{"TraceBlock.entries[0].status", sizeof(Header) + offsetof(Entry, status)},
    };
}

// The stride of every array the host writes or reads element by element: an array's own stride
// where reflection gives it, else (arrays of structs) half the size of a probe block of two.
template <typename Real>
std::map<std::string, std::size_t> arrayStrides() {
    std::map<std::string, std::size_t> strides{{"NodeProbe", sizeof(GpuNode<Real>)},
                                               {"LookProbe", sizeof(GpuLook<Real>)},
                                               {"LightProbe", sizeof(GpuLight<Real>)}};
    strides.insert({{"TraceEntryProbe", sizeof(GpuTraceEntry<Real>)},
                    {"PixelCarryProbe", sizeof(GpuPixelCarry)},
                    {"pixels", sizeof(GpuPixel)},
                    {"classes", sizeof(GpuPixelClass)},
                    {"encodedPixels", sizeof(GpuEncodedPixel)},
                    {"aovs", sizeof(GpuAovPixel)}});
    return strides;
}

struct Reflected {
    int offset;
    int arrayStride;
};

// A compute shader that declares every shared block and uses one member of each, so the
// reflection keeps them all; `defines` picks the variant.
std::map<std::string, Reflected> reflectBlocks(const std::string& defines) {
    const std::string source =
        "#version 450\n#extension GL_GOOGLE_include_directive : require\n" + defines +
        "#include \"scene_data.glsl\"\n"
        "#include \"render_outputs.glsl\"\n"
        "#include \"inspect_hooks.glsl\"\n"
        "#include \"light_batches.glsl\"\n"
        "#ifdef HEXRAY_UNIFORM_SCENE\n"
        "#define PROBE(binding_) layout(std140, set = 1, binding = binding_) uniform\n"
        "#else\n"
        "#define PROBE(binding_) layout(std430, set = 1, binding = binding_) readonly buffer\n"
        "#endif\n"
        "PROBE(0) NodeProbe { Node nodeProbe[2]; };\n"
        "PROBE(1) LightProbe { Light lightProbe[2]; };\n"
        "PROBE(4) LookProbe { Look lookProbe[2]; };\n"
        "layout(std430, set = 1, binding = 2) readonly buffer TraceEntryProbe {\n"
        "    TraceEntry traceEntryProbe[2];\n"
        "};\n"
        "layout(std430, set = 1, binding = 3) readonly buffer PixelCarryProbe {\n"
        "    PixelCarry pixelCarryProbe[2];\n"
        "};\n"
        "void main() {\n"
        "    pixels[0] = vec4(frame.nodeCount + nodeGeometryKind(0u) + lookShaderKind(0u) + band.firstRow);\n"
        "    classes[0] = uvec2(float(lightPower(0u).x));\n"
        "    encodedPixels[0] = trace.header.request.x + trace.entries[0].status.x;\n"
        "    aovs[0] = vec4(nodeProbe[1].look + lookProbe[1].shaderKind + lightProbe[1].power.x + "
        "traceEntryProbe[1].color.x + pixelCarryProbe[1].flags + carry[0].flags);\n"
        "}\n";
    glslang::InitializeProcess();
    glslang::TShader shader(EShLangCompute);
    const char* text = source.c_str();
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    ShaderLibraryIncluder includer;
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    std::map<std::string, Reflected> members;
    if (!shader.parse(GetDefaultResources(), 450, false, messages, includer)) {
        ADD_FAILURE() << shader.getInfoLog();
        return members;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages) || !program.buildReflection(EShReflectionAllBlockVariables)) {
        ADD_FAILURE() << program.getInfoLog();
        return members;
    }
    for (int i = 0; i < program.getNumUniformVariables(); ++i) {
        const glslang::TObjectReflection& member = program.getUniform(i);
        members[member.name] = {member.offset, member.arrayStride};
    }
    for (int i = 0; i < program.getNumBufferVariables(); ++i) {
        const glslang::TObjectReflection& member = program.getBufferVariable(i);
        members[member.name] = {member.offset, member.topLevelArrayStride};
    }
    // The probe blocks: an element's stride is half the block.
    const auto addProbe = [&](const glslang::TObjectReflection& block) {
        if (block.name.ends_with("Probe")) {
            members[block.name] = {0, block.size / 2};
        }
    };
    for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
        addProbe(program.getUniformBlock(i));
    }
    for (int i = 0; i < program.getNumBufferBlocks(); ++i) {
        addProbe(program.getBufferBlock(i));
    }
    return members;
}

std::string listed(const std::map<std::string, Reflected>& members) {
    std::string text;
    for (const auto& [name, member] : members) {
        text +=
            "  " + name + " @" + std::to_string(member.offset) + " stride " + std::to_string(member.arrayStride) + "\n";
    }
    return text;
}

struct Variant {
    const char* name;
    const char* defines;
    bool f64;
    bool texels;  // nodes and lights in texel buffers
};

void PrintTo(const Variant& variant, std::ostream* out) {
    *out << variant.name;
}

class GpuLayoutTest : public ::testing::TestWithParam<Variant> {};

TEST_P(GpuLayoutTest, EveryMemberAndStrideIsWhereTheCppMirrorPutsIt) {
    const Variant variant = GetParam();
    const std::map<std::string, Reflected> reflected = reflectBlocks(variant.defines);
    ASSERT_FALSE(reflected.empty());
    const std::string nodes = variant.texels ? "nodeProbe" : "nodes";
    const std::string looks = variant.texels ? "lookProbe" : "looks";
    const std::string lights = variant.texels ? "lightProbe" : "lights";
    const std::size_t looksStart =
        variant.texels ? 0 : SMALL_SCENE_CAPACITY * (variant.f64 ? sizeof(GpuNode<double>) : sizeof(GpuNode<float>));
    std::vector<Member> expected = variant.f64 ? sceneMembers<double>(nodes, looks, looksStart, lights)
                                               : sceneMembers<float>(nodes, looks, looksStart, lights);
    const std::vector<Member> outputs = variant.f64 ? outputMembers<double>() : outputMembers<float>();
    expected.insert(expected.end(), outputs.begin(), outputs.end());
    for (const Member& member : expected) {
        const auto found = reflected.find(member.name);
        ASSERT_NE(found, reflected.end()) << member.name << " is not in the GLSL; it has:\n" << listed(reflected);
        EXPECT_EQ(std::size_t(found->second.offset), member.offset) << member.name;
    }
    const auto strides = variant.f64 ? arrayStrides<double>() : arrayStrides<float>();
    for (const auto& [name, stride] : strides) {
        const auto found = reflected.find(name);
        ASSERT_NE(found, reflected.end()) << name << " is not in the GLSL; it has:\n" << listed(reflected);
        EXPECT_EQ(std::size_t(found->second.arrayStride), stride) << name;
    }
    // Every member the GLSL declares has its C++ mirror: padding, the probes, the texel buffers
    // (samplers, not blocks: their texels are asserted in gpu_layout.h), the other elements
    // of a uniform array ("nodes[9].look") and the second name reflection gives a member reached
    // through a variable index ("nodes.look") aside.
    const auto mirrored = [&](std::string name) {
        name = std::regex_replace(name, std::regex(R"(\[[0-9]+\])"), "[0]");
        return std::any_of(expected.begin(), expected.end(), [&](const Member& m) { return m.name == name; }) ||
               strides.count(name) > 0 || name.find("unused") != std::string::npos ||
               name.find("Probe") != std::string::npos || name.find("probe") != std::string::npos ||
               name.ends_with("Texels");
    };
    const auto secondName = [&](const std::string& name) {
        for (std::size_t dot = name.find('.'); dot != std::string::npos; dot = name.find('.', dot + 1)) {
            std::string indexed = name;
            if (reflected.count(indexed.insert(dot, "[0]")) > 0) {
                return true;
            }
        }
        return false;
    };
    for (const auto& [name, member] : reflected) {
        EXPECT_TRUE(mirrored(name) || secondName(name)) << name << " has no C++ mirror in this test";
    }
}

INSTANTIATE_TEST_SUITE_P(
    Variants, GpuLayoutTest,
    ::testing::Values(Variant{"TexelsF32", "", false, true}, Variant{"TexelsF64", "#define HEXRAY_F64\n", true, true},
                      Variant{"UniformF32", "#define HEXRAY_UNIFORM_SCENE\n", false, false},
                      Variant{"UniformF64", "#define HEXRAY_F64\n#define HEXRAY_UNIFORM_SCENE\n", true, false}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace hexray
