#include "stochtex/gpu/engine_shaders.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <functional>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace stochtex {

namespace {

// Compiled around the include: a fragment shader whose main calls every
// entry point (glslang drops functions nothing calls), with inputs and an
// output whose names mark what the flavours strip again.
const char* kProbeMain =
    "layout(location = 0) in vec2 stochtexProbeUv;\n"
    "layout(location = 1) in vec3 stochtexProbeNormal;\n"
    "layout(location = 0) out vec4 stochtexProbeColour;\n"
    "void main() {\n"
    "    vec3 p = vec3(stochtexProbeUv, 0.5);\n"
    "    stochtexProbeColour = stochtex_sample(stochtexProbeUv) +\n"
    "        stochtex_sample_grad(stochtexProbeUv, vec2(0.01, 0.0), vec2(0.0, 0.01)) +\n"
    "        stochtex_sample_triplanar(p, stochtexProbeNormal) +\n"
    "        stochtex_sample_triplanar_grad(p, stochtexProbeNormal, vec3(0.01, 0.0, 0.0), vec3(0.0, 0.01, 0.0));\n"
    "}\n";
constexpr const char* kProbeMark = "stochtexProbe";

std::vector<unsigned> spirvOf(const std::string& include) {
    static std::once_flag initialised;
    std::call_once(initialised, [] { glslang::InitializeProcess(); });  // process-wide, never finalised
    const std::string source =
        "#version 450\n#define STOCHTEX_BINDING(n) layout(set = 0, binding = n)\n" + include + "\n" + kProbeMain;
    const char* text = source.c_str();
    glslang::TShader shader(EShLangFragment);
    shader.setStrings(&text, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangFragment, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    const auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 450, false, messages))
        throw std::logic_error(std::string("engine shaders: the include does not compile to SPIR-V:\n") +
                               shader.getInfoLog());
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw std::logic_error(std::string("engine shaders: the include does not link:\n") + program.getInfoLog());
    std::vector<unsigned> spirv;
    glslang::GlslangToSpv(*program.getIntermediate(EShLangFragment), spirv);
    return spirv;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

// Removes the first top-level block whose opening line satisfies `opens`
// (that line through the one that closes its braces) and returns its lines;
// empty when there is none.
std::vector<std::string> takeBlock(std::vector<std::string>& lines,
                                   const std::function<bool(const std::string&)>& opens) {
    for (size_t first = 0; first < lines.size(); ++first) {
        if (!opens(lines[first])) continue;
        int depth = 0;
        bool opened = false;
        for (size_t last = first; last < lines.size(); ++last) {
            for (char c : lines[last]) {
                depth += c == '{' ? 1 : c == '}' ? -1 : 0;
                opened = opened || c == '{';
            }
            if (opened && depth == 0) {
                std::vector<std::string> block(lines.begin() + long(first), lines.begin() + long(last) + 1);
                lines.erase(lines.begin() + long(first), lines.begin() + long(last) + 1);
                if (first < lines.size() && lines[first].empty()) lines.erase(lines.begin() + long(first));
                return block;
            }
        }
        throw std::logic_error("engine shaders: unbalanced braces after: " + lines[first]);
    }
    return {};
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The probe's main sets the program's mutable globals (the lean directions)
// to their initial values before it calls anything: those statements,
// name → value, become the globals' initialisers when main goes.
std::map<std::string, std::string> globalInitialisers(const std::vector<std::string>& mainBlock,
                                                      const std::set<std::string>& globals) {
    static const std::regex assignment(R"(^\s*(\w+) = (.*);$)");
    std::map<std::string, std::string> out;
    std::smatch m;
    for (const std::string& line : mainBlock)
        if (std::regex_match(line, m, assignment) && globals.count(m[1]) && !out.count(m[1])) out[m[1]] = m[2];
    return out;
}

void dropProbeLines(std::vector<std::string>& lines) {
    std::erase_if(lines, [](const std::string& l) { return l.find(kProbeMark) != std::string::npos; });
}

std::string replaceAll(const std::string& text, const std::regex& pattern, const std::string& with) {
    return std::regex_replace(text, pattern, with);
}

const char* kEntryPoints =
    "// Entry points, uv in example periods (all return linear-light RGB, alpha 1):\n"
    "//   stochtex_sample(uv)                            footprint from this pixel's derivatives\n"
    "//   stochtex_sample_grad(uv, ddx, ddy)             footprint from explicit derivatives of uv\n"
    "//   stochtex_sample_triplanar(p, n)                three projections of p blended by the normal n\n"
    "//   stochtex_sample_triplanar_grad(p, n, dpdx, dpdy)\n";

std::string hlslFlavour(const std::vector<unsigned>& spirv) {
    spirv_cross::CompilerHLSL compiler(spirv);
    spirv_cross::CompilerHLSL::Options options;
    options.shader_model = 50;
    compiler.set_hlsl_options(options);
    std::vector<std::string> lines = splitLines(compiler.compile());
    dropProbeLines(lines);
    takeBlock(lines, [](const std::string& l) { return l == "struct SPIRV_Cross_Input"; });
    takeBlock(lines, [](const std::string& l) { return l == "struct SPIRV_Cross_Output"; });
    takeBlock(lines, [](const std::string& l) { return startsWith(l, "SPIRV_Cross_Output main("); });
    static const std::regex global(R"(^static (\w+) (\w+);$)");
    std::set<std::string> globals;
    std::smatch m;
    for (const std::string& l : lines)
        if (std::regex_match(l, m, global)) globals.insert(m[2]);
    const auto initial =
        globalInitialisers(takeBlock(lines, [](const std::string& l) { return l == "void frag_main()"; }), globals);
    for (std::string& l : lines)
        if (std::regex_match(l, m, global) && initial.count(m[2]))
            l = "static " + m[1].str() + " " + m[2].str() + " = " + initial.at(m[2]) + ";";
    std::string body = joinLines(lines);
    // Registers behind a macro (an engine that assigns its own, as Unity
    // does, defines it empty); samplers named as Unity pairs them with
    // their textures (sampler_<texture>); the block's one member by its
    // GLSL name.
    body = replaceAll(body, std::regex(R"( : register\((\w+)\))"), " STOCHTEX_REGISTER($1)");
    body = replaceAll(body, std::regex(R"(\b_(\w+)_sampler\b)"), "sampler_$1");
    body = replaceAll(body, std::regex(R"(\b_[0-9]+_uPattern\b)"), "uPattern");
    return std::string(
               "// stochtex: filtered colour-mapped noise (Grenier et al. 2022) as HLSL (shader model 5.0),\n"
               "// translated by SPIRV-Cross from the SPIR-V of stochtex.glsl (`stochtex bake`): the same\n"
               "// program, textures and parameter block (cbuffer PatternParameters, std140-compatible).\n") +
           kEntryPoints +
           "// Lean programs: set gEyeDirection and gLightDirection (static globals) before sampling.\n"
           "#ifndef STOCHTEX_REGISTER\n#define STOCHTEX_REGISTER(r) : register(r)\n#endif\n" +
           body;
}

const char* kUnityFlavour = R"(// stochtex for Unity: Shader Graph Custom Function entry points over stochtex.hlsl.
// In a Custom Function node: Type File, Source this file, Name one of
// StochtexSample, StochtexSampleGrad, StochtexSampleTriplanar,
// StochtexSampleTriplanarGrad (Shader Graph appends _float or _half), with
// the inputs and the output below; in a hand-written shader, #include it and
// call the functions. Colour is linear-light RGB (Unity's linear colour
// space). The textures are global names (Shader.SetGlobalTexture or the
// material, point-filtered, no mip maps generated: every level is a file of
// the export); the PatternParameters block is set with
// Shader.SetGlobalConstantBuffer (README.md lists its bytes).
#ifndef STOCHTEX_UNITY_INCLUDED
#define STOCHTEX_UNITY_INCLUDED
#define STOCHTEX_REGISTER(r)  // Unity assigns the registers
#include "stochtex.hlsl"

void StochtexSample_float(float2 UV, out float4 Colour) { Colour = stochtex_sample(UV); }
void StochtexSampleGrad_float(float2 UV, float2 DDX, float2 DDY, out float4 Colour) {
    Colour = stochtex_sample_grad(UV, DDX, DDY);
}
void StochtexSampleTriplanar_float(float3 Position, float3 Normal, out float4 Colour) {
    Colour = stochtex_sample_triplanar(Position, Normal);
}
void StochtexSampleTriplanarGrad_float(float3 Position, float3 Normal, float3 DPDX, float3 DPDY, out float4 Colour) {
    Colour = stochtex_sample_triplanar_grad(Position, Normal, DPDX, DPDY);
}

// Half-precision graphs: the program runs in float (its hashes and
// variances need it), the colour is rounded once at the end.
void StochtexSample_half(float2 UV, out half4 Colour) { Colour = half4(stochtex_sample(UV)); }
void StochtexSampleGrad_half(float2 UV, float2 DDX, float2 DDY, out half4 Colour) {
    Colour = half4(stochtex_sample_grad(UV, DDX, DDY));
}
void StochtexSampleTriplanar_half(float3 Position, float3 Normal, out half4 Colour) {
    Colour = half4(stochtex_sample_triplanar(Position, Normal));
}
void StochtexSampleTriplanarGrad_half(float3 Position, float3 Normal, float3 DPDX, float3 DPDY, out half4 Colour) {
    Colour = half4(stochtex_sample_triplanar_grad(Position, Normal, DPDX, DPDY));
}

#endif
)";

// Godot's shading language is GLSL ES 3.00 without uniform blocks, mutable
// globals, layout qualifiers or precision statements, and with hints on its
// uniforms: the ES translation, rewritten into it.
std::pair<std::string, std::vector<std::string>> godotFlavour(const std::vector<unsigned>& spirv,
                                                              const std::map<std::string, std::string>& values) {
    spirv_cross::CompilerGLSL compiler(spirv);
    spirv_cross::CompilerGLSL::Options options;
    options.es = true;
    options.version = 300;
    options.vulkan_semantics = false;
    compiler.set_common_options(options);
    std::string text = compiler.compile();
    text = replaceAll(text, std::regex(R"(\b(highp|mediump|lowp) )"), "");
    std::vector<std::string> lines = splitLines(text);
    std::erase_if(lines, [](const std::string& l) { return startsWith(l, "#version") || startsWith(l, "precision"); });
    dropProbeLines(lines);

    // The parameter block: one uniform per member of PatternParams.
    const std::vector<std::string> block =
        takeBlock(lines, [](const std::string& l) { return l == "layout(std140) uniform PatternParameters"; });
    std::smatch m;
    static const std::regex closing(R"(^\} (\w+);$)");
    if (block.empty() || !std::regex_match(block.back(), m, closing))
        throw std::logic_error("engine shaders: no PatternParameters block in the ES translation");
    const std::string instance = m[1];
    std::vector<std::pair<std::string, std::string>> members;  // (type, name)
    {
        std::vector<std::string> copy = lines;
        static const std::regex member(R"(^\s+(\w+) (\w+);$)");
        for (const std::string& l : takeBlock(copy, [](const std::string& l) { return l == "struct PatternParams"; }))
            if (std::regex_match(l, m, member)) members.emplace_back(m[1], m[2]);
    }
    if (members.empty()) throw std::logic_error("engine shaders: no PatternParams struct in the ES translation");

    // Mutable globals become uniforms (Godot has no others), their initial
    // values the uniforms' defaults; the host sets them per material.
    static const std::regex global(R"(^(\w+) (\w+);$)");
    std::set<std::string> globals;
    for (const std::string& l : lines)
        if (std::regex_match(l, m, global)) globals.insert(m[2]);
    const auto initial =
        globalInitialisers(takeBlock(lines, [](const std::string& l) { return l == "void main()"; }), globals);
    static const std::regex sampler(R"(^uniform (sampler2D|sampler2DArray) (\w+);$)");
    std::vector<std::string> out;
    for (const std::string& l : lines) {
        if (std::regex_match(l, m, global) && globals.count(m[2])) {
            out.push_back("uniform " + m[1].str() + " " + m[2].str() +
                          (initial.count(m[2]) ? " = " + initial.at(m[2]) : "") + ";");
        } else if (std::regex_match(l, m, sampler)) {
            // Every read is a texelFetch of an explicit level: no filtering, no wrap.
            out.push_back("uniform " + m[1].str() + " " + m[2].str() + " : filter_nearest, repeat_disable;");
        } else {
            out.push_back(l);
        }
    }
    std::string body = joinLines(out);
    body = replaceAll(body, std::regex("\\b" + instance + "\\.uPattern\\.(\\w+)"), "stochtex_$1");
    // The block passed whole (if ever): a constructor of the uniforms.
    std::string constructor = "PatternParams(";
    for (size_t i = 0; i < members.size(); ++i) constructor += (i ? ", stochtex_" : "stochtex_") + members[i].second;
    const std::regex whole("\\b" + instance + "\\.uPattern\\b");
    const bool passedWhole = std::regex_search(body, whole);
    body = replaceAll(body, whole, constructor + ")");
    std::vector<std::string> uniforms, parameterNames;
    for (const auto& [type, name] : members) {
        const std::string uniform = "stochtex_" + name;
        if (!passedWhole && !std::regex_search(body, std::regex("\\b" + uniform + "\\b"))) continue;
        const auto value = values.find(name);
        uniforms.push_back("uniform " + type + " " + uniform + (value != values.end() ? " = " + value->second : "") +
                           ";");
        parameterNames.push_back(uniform);
    }
    // SPIRV-Cross names temporaries _<id>; Godot reserves nothing of the
    // kind, but a name of ours reads better in its error messages.
    body = replaceAll(body, std::regex(R"(\b_([0-9]+)\b)"), "stochtex_t$1");
    std::string header =
        "// stochtex: filtered colour-mapped noise (Grenier et al. 2022) as a Godot 4 shader include,\n"
        "// translated by SPIRV-Cross from the SPIR-V of stochtex.glsl (`stochtex bake`).\n"
        "// In a spatial (or canvas_item) shader: #include \"stochtex.gdshaderinc\", then in fragment():\n"
        "//   ALBEDO = stochtex_sample(UV * 8.0).rgb;  // linear-light RGB, as ALBEDO takes it\n";
    header += kEntryPoints;
    header +=
        "// Bind the samplers (README.md; each level of a pyramid is a file). The parameters'\n"
        "// defaults are this export's values.\n";
    header += "// Lean programs: gEyeDirection and gLightDirection are uniforms here (one direction per material).\n";
    std::string decls;
    for (const std::string& u : uniforms) decls += u + "\n";
    return {header + "\n" + decls + body, parameterNames};
}

}  // namespace

EngineShaders engineShaders(const std::string& include, const std::map<std::string, std::string>& parameterValues) {
    const std::vector<unsigned> spirv = spirvOf(include);
    EngineShaders out;
    try {
        out.hlsl = hlslFlavour(spirv);
        auto [godot, parameters] = godotFlavour(spirv, parameterValues);
        out.godot = std::move(godot);
        out.godotParameters = std::move(parameters);
    } catch (const spirv_cross::CompilerError& e) {
        throw std::logic_error(std::string("engine shaders: SPIRV-Cross: ") + e.what());
    }
    out.unity = kUnityFlavour;
    out.godotShader = std::string(
                          "// stochtex: a Godot 4 spatial shader (stochtex.gdshaderinc's text inlined, then a\n"
                          "// fragment function): assign it to a ShaderMaterial and bind its samplers.\n"
                          "shader_type spatial;\n\n") +
                      out.godot +
                      "\n// Example periods across the mesh's UV square.\n"
                      "uniform float stochtex_tiling = 8.0;\n\n"
                      "void fragment() {\n"
                      "    ALBEDO = stochtex_sample(UV * stochtex_tiling).rgb;  // linear RGB, as ALBEDO takes it\n"
                      "}\n";
    return out;
}

}  // namespace stochtex
