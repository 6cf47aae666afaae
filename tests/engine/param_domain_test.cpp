// The parameters' domains (param_spec.h): enum labels that parse and format, number ranges
// that refuse what lies outside with a message naming the range, preset-then-values order,
// and the input flags that voxray-cli and the workstation share.
#include <sstream>

#include <gtest/gtest.h>

#include "voxray/engine/input_flags.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/error.h"
#include "voxray/io/orientation.h"

namespace voxray {
namespace {

template <class Parse>
std::string errorOf(Parse parse) {
  try {
    parse();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string renderError(const std::string& key, const std::string& value) {
  return errorOf([&] {
    RenderParams p;
    findRenderParamSpec(key).parse(p, value);
  });
}

TEST(ParamDomain, EveryEnumSpecRoundTripsEveryLabel) {
  int enums = 0;
  for (const ParamSpec& spec : renderParamSpecs()) {
    const auto& labels = spec.domain.labels;
    if (labels.empty()) continue;
    ++enums;
    std::string hint;
    for (const EnumLabel& l : labels) {
      hint += (hint.empty() ? "" : "|") + l.name;
      EXPECT_FALSE(l.title.empty()) << spec.key << " " << l.name;
      RenderParams p;
      spec.parse(p, l.name);
      EXPECT_EQ(spec.format(p), l.name) << spec.key;
      for (const std::string& alias : l.aliases) {
        RenderParams q;
        spec.parse(q, alias);
        EXPECT_EQ(spec.format(q), l.name) << spec.key << " " << alias;
      }
    }
    EXPECT_EQ(spec.valueHint, hint) << spec.key;
    EXPECT_EQ(renderError(spec.key, "nonsense"),
              "--" + spec.key + ": 'nonsense' is not one of " + labelNames(labels, ", "));
  }
  EXPECT_EQ(enums, 5);  // mode, gradient, interp, projection, lighting
}

TEST(ParamDomain, EnumNamesComeFromTheSpecTables) {
  const auto& modes = findRenderParamSpec("mode").domain.labels;
  for (size_t i = 0; i < modes.size(); ++i) {
    EXPECT_EQ(toString(Mode(i)), modes[i].name);
    EXPECT_EQ(parseMode(modes[i].name), Mode(i));
  }
  const auto& gradients = findRenderParamSpec("gradient").domain.labels;
  ASSERT_EQ(gradients.size(), 3u);
  EXPECT_EQ(toString(Gradient::ZuckerHummel), gradients[2].name);
  EXPECT_EQ(parseGradient("zh"), Gradient::ZuckerHummel);
  EXPECT_EQ(parseInterp("trilinear"), Interp::Linear);
  EXPECT_EQ(std::string(toString(Interp::Nearest)), "nearest");
}

TEST(ParamDomain, NumbersOutsideTheRangeAreRefusedNamingIt) {
  EXPECT_EQ(renderError("shininess", "0"), "--shininess: must be greater than 0, got '0'");
  EXPECT_EQ(renderError("ambient", "1.5"), "--ambient: must lie in 0 ... 1, got '1.5'");
  EXPECT_EQ(renderError("refine", "17"), "--refine: must lie in 0 ... 16, got '17'");
  EXPECT_EQ(renderError("step", "-1"), "--step: must be at least 0, got '-1'");
  EXPECT_EQ(renderError("fov", "170"),
            "--fov: must be greater than 0 and less than 170, got '170'");
  EXPECT_EQ(renderError("clip", "0,1.5,0,1,0,1"),
            "--clip: must lie in 0 ... 1, got '0,1.5,0,1,0,1'");
  // The ends themselves, where the range includes them.
  EXPECT_EQ(renderError("ambient", "1"), "no error");
  EXPECT_EQ(renderError("refine", "0"), "no error");
  // Shininess has no upper end: the panel's old cap of 256 was the panel's alone.
  RenderParams p;
  findRenderParamSpec("shininess").parse(p, "5000");
  EXPECT_DOUBLE_EQ(p.light.shininess, 5000.0);
}

TEST(ParamDomain, EverySingleNumberSpecChecksItsDomain) {
  int checked = 0;
  for (const ParamSpec& spec : renderParamSpecs()) {
    const ParamDomain& d = spec.domain;
    if (!d.labels.empty() || !(d.min || d.max)) continue;
    double inside = d.min ? *d.min + 1.0 : *d.max - 1.0;
    if (d.max && *d.max < inside) inside = (*d.min + *d.max) / 2;
    // Lists (size, clip) have their own messages: only single numbers are checked here.
    if (renderError(spec.key, number(inside)) != "no error") continue;
    ++checked;
    EXPECT_TRUE(d.contains(inside)) << spec.key;
    if (d.min) {
      std::string below = number(*d.min - 1.0);
      EXPECT_EQ(renderError(spec.key, below),
                "--" + spec.key + ": must " + d.rangeText() + ", got '" + below + "'");
    }
    if (d.max) {
      std::string above = number(*d.max + 1.0);
      EXPECT_EQ(renderError(spec.key, above),
                "--" + spec.key + ": must " + d.rangeText() + ", got '" + above + "'");
    }
  }
  // opacity-unit, step, refine, adaptive, segment-blend, early-termination, zoom, distance,
  // fov, ambient, diffuse, specular, shininess
  EXPECT_EQ(checked, 13);
}

TEST(ParamDomain, UiEndsLieInsideTheDomain) {
  for (const ParamSpec& spec : renderParamSpecs()) {
    const ParamDomain& d = spec.domain;
    EXPECT_TRUE(!d.uiMin || d.contains(*d.uiMin)) << spec.key;
    EXPECT_TRUE(!d.uiMax || d.contains(*d.uiMax)) << spec.key;
  }
  EXPECT_DOUBLE_EQ(*findRenderParamSpec("shininess").domain.uiMax, 1024.0);
}

TEST(ApplyRenderValues, PresetFirstThenTheValuesGiven) {
  RenderParams p;
  p.presetShiftHu = 200.0;  // tuned for another preset: dropped
  applyRenderValues(p, {{"preset", "Iso-Bone"}, {"iso", "250"}, {"zoom", "2"}});
  EXPECT_EQ(p.mode, Mode::Iso);
  EXPECT_DOUBLE_EQ(p.isoLo, 250.0);  // the value given, not the preset's 400
  EXPECT_DOUBLE_EQ(p.camera.zoom, 2.0);
  EXPECT_DOUBLE_EQ(p.presetShiftHu, 0.0);
  RenderParams q;
  applyRenderValues(q, {{"mode", "mip"}, {"preset", "CT-Bone"}});
  EXPECT_EQ(q.mode, Mode::Mip);  // CT-Bone brings dvr; the flag wins whatever the map order
  EXPECT_EQ(q.preset, "CT-Bone");
  EXPECT_EQ(errorOf([] {
              RenderParams r;
              applyRenderValues(r, {{"colour", "red"}});
            }),
            "render parameters: unknown key 'colour'");
}

TEST(InputFlags, ReadEveryRawFlag) {
  LoadOptions o = loadOptionsFromFlags({{"raw-dims", "256,256,113"},
                                        {"raw-type", "u16"},
                                        {"raw-endian", "big"},
                                        {"raw-spacing", "0.5,0.5,2"},
                                        {"raw-offset", "64"},
                                        {"raw-rescale", "2,-1024"},
                                        {"raw-range", "3-115"},
                                        {"raw-axes", "LPI"},
                                        {"series", "7"}});
  ASSERT_TRUE(o.raw);
  EXPECT_EQ(o.raw->dims, glm::ivec3(256, 256, 113));
  EXPECT_EQ(o.raw->type, SampleType::U16);
  EXPECT_EQ(o.raw->order, ByteOrder::Big);
  EXPECT_EQ(o.raw->spacingMm, glm::dvec3(0.5, 0.5, 2.0));
  EXPECT_EQ(o.raw->headerBytes, 64u);
  EXPECT_DOUBLE_EQ(o.raw->slope, 2.0);
  EXPECT_DOUBLE_EQ(o.raw->intercept, -1024.0);
  EXPECT_EQ(o.raw->range, std::make_pair(3, 115));
  EXPECT_EQ(o.raw->direction, directionFromAxesCode("LPI"));
  EXPECT_EQ(o.series, "7");
  // What the specs write reads back to the same options.
  std::map<std::string, std::string> written;
  for (const InputFlagSpec& spec : inputFlagSpecs()) written[spec.key] = spec.format(o);
  LoadOptions again = loadOptionsFromFlags(written);
  for (const InputFlagSpec& spec : inputFlagSpecs())
    EXPECT_EQ(spec.format(again), written[spec.key]) << spec.key;
}

TEST(InputFlags, BadFlagsSayWhatIsWrong) {
  auto error = [](std::map<std::string, std::string> given) {
    return errorOf([&] { loadOptionsFromFlags(given); });
  };
  EXPECT_EQ(error({{"raw-spacing", "1,1,2"}}),
            "raw flags need --raw-dims X,Y[,Z] to read INPUT as raw data");
  EXPECT_EQ(error({{"raw-dims", "256,0"}}), "--raw-dims: must be at least 1, got '256,0'");
  EXPECT_EQ(error({{"raw-dims", "256"}}),
            "--raw-dims: expected 2 to 3 comma-separated numbers, got '256'");
  EXPECT_EQ(error({{"raw-dims", "2,2"}, {"raw-spacing", "1,0,1"}}),
            "--raw-spacing: must be greater than 0, got '1,0,1'");
  EXPECT_EQ(error({{"raw-dims", "2,2"}, {"raw-range", "7"}}),
            "--raw-range: expected FIRST-LAST, e.g. 1-113, got '7'");
  EXPECT_EQ(error({{"raw-dims", "2,2"}, {"raw-offset", "-4"}}),
            "--raw-offset: must be at least 0, got '-4'");
  EXPECT_EQ(error({{"raw-colour", "red"}}), "input flags: unknown flag --raw-colour");
  EXPECT_FALSE(loadOptionsFromFlags({{"series", "3"}}).raw);
}

TEST(InputFlags, EnumLabelsFollowTheEnumsOrder) {
  const auto& types = findInputFlagSpec("raw-type").domain.labels;
  ASSERT_EQ(types.size(), 4u);
  for (size_t i = 0; i < types.size(); ++i)
    EXPECT_EQ(parseSampleType(types[i].name), SampleType(i));
  const auto& orders = findInputFlagSpec("raw-endian").domain.labels;
  ASSERT_EQ(orders.size(), 2u);
  for (size_t i = 0; i < orders.size(); ++i)
    EXPECT_EQ(parseByteOrder(orders[i].name), ByteOrder(i));
}

}  // namespace
}  // namespace voxray
