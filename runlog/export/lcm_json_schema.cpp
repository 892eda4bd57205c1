#include "runlog/export/lcm_json_schema.hpp"

#include <cctype>
#include <regex>
#include <stdexcept>
#include <vector>

#include "evolve/messages/build.hpp"

namespace robozoo {

namespace {

struct Field {
  std::string type, name;
  std::vector<std::string> dims;  // as written: a number or the name of a count field
};

std::string strip_comments(const std::string& text) {
  static const std::regex line_comment("//[^\n]*");
  static const std::regex block_comment("/\\*[\\s\\S]*?\\*/");
  return std::regex_replace(std::regex_replace(text, block_comment, " "), line_comment, " ");
}

std::vector<Field> struct_fields(const std::string& name, const std::string& source) {
  const std::string text = strip_comments(source);
  const std::regex body_re("struct\\s+" + name + "\\s*\\{([^}]*)\\}");
  std::smatch body;
  if (!std::regex_search(text, body, body_re)) throw std::invalid_argument("lcmtypes: no struct " + name);
  std::vector<Field> fields;
  static const std::regex decl_re(
      "^\\s*([A-Za-z_][A-Za-z0-9_.]*)\\s+([A-Za-z_][A-Za-z0-9_]*)((\\s*\\[[^\\]]+\\])*)\\s*$");
  static const std::regex dim_re("\\[\\s*([^\\]\\s]+)\\s*\\]");
  const std::string declarations = body[1].str();
  size_t start = 0;
  for (size_t semi; (semi = declarations.find(';', start)) != std::string::npos; start = semi + 1) {
    const std::string decl = declarations.substr(start, semi - start);
    std::smatch m;
    if (!std::regex_match(decl, m, decl_re))
      throw std::invalid_argument("lcmtypes: " + name + ": cannot read declaration '" + decl + "'");
    Field f{m[1].str(), m[2].str(), {}};
    const std::string dims = m[3].str();
    for (auto it = std::sregex_iterator(dims.begin(), dims.end(), dim_re); it != std::sregex_iterator(); ++it)
      f.dims.push_back((*it)[1].str());
    fields.push_back(f);
  }
  if (declarations.find_first_not_of(" \t\r\n", start) != std::string::npos)
    throw std::invalid_argument("lcmtypes: " + name + ": text after the last ';'");
  return fields;
}

nlohmann::json integer(long long lo, long long hi) { return {{"type", "integer"}, {"minimum", lo}, {"maximum", hi}}; }

nlohmann::json scalar_schema(const std::string& type, const std::map<std::string, std::string>& sources) {
  if (type == "int8_t") return integer(-128, 127);
  if (type == "byte") return integer(0, 255);
  if (type == "int16_t") return integer(-32768, 32767);
  if (type == "int32_t") return integer(-2147483648LL, 2147483647LL);
  if (type == "int64_t") return {{"type", "integer"}};
  if (type == "double" || type == "float") return {{"type", "number"}};
  if (type == "string") return {{"type", "string"}};
  if (type == "boolean") return {{"type", "boolean"}};
  const std::string local = type.substr(type.rfind('.') + 1);  // robozoo.sphere_t -> sphere_t
  return lcm_json_schema(local, sources);
}

}  // namespace

nlohmann::json lcm_json_schema(const std::string& name, const std::map<std::string, std::string>& sources) {
  const auto it = sources.find(name);
  if (it == sources.end()) throw std::invalid_argument("lcmtypes: unknown type " + name);
  nlohmann::json properties = nlohmann::json::object();
  nlohmann::json required = nlohmann::json::array();
  for (const Field& f : struct_fields(name, it->second)) {
    nlohmann::json s = scalar_schema(f.type, sources);
    for (auto d = f.dims.rbegin(); d != f.dims.rend(); ++d) {
      nlohmann::json array = {{"type", "array"}, {"items", s}};
      if (std::isdigit(static_cast<unsigned char>((*d)[0]))) {
        const long n = std::stol(*d);
        array["minItems"] = n;
        array["maxItems"] = n;
      }
      s = std::move(array);
    }
    properties[f.name] = std::move(s);
    required.push_back(f.name);
  }
  return {{"title", "robozoo." + name},
          {"type", "object"},
          {"properties", properties},
          {"required", required},
          {"additionalProperties", false}};
}

std::string lcm_type_of_channel(const std::string& channel) {
  if (channel == kChannelRun) return "run_t";
  if (channel == kChannelGeneration) return "generation_t";
  if (channel == kChannelGenome) return "cppn_genome_t";
  if (channel == kChannelMorphology) return "morphology_t";
  if (channel == kChannelPose) return "pose_t";
  return "";
}

}  // namespace robozoo
