#include "voxray/engine/param_spec.h"

#include <algorithm>

#include "text_parse.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

// One end of the range: where it lies and whether the range excludes it.
ParamDomain& setEnd(ParamDomain& d, std::optional<double>& end, bool& excluded, double v,
                    bool exclude) {
  end = v;
  excluded = exclude;
  return d;
}

}  // namespace

ParamDomain& ParamDomain::atLeast(double v) { return setEnd(*this, min, minExclusive, v, false); }
ParamDomain& ParamDomain::above(double v) { return setEnd(*this, min, minExclusive, v, true); }
ParamDomain& ParamDomain::atMost(double v) { return setEnd(*this, max, maxExclusive, v, false); }
ParamDomain& ParamDomain::below(double v) { return setEnd(*this, max, maxExclusive, v, true); }

ParamDomain& ParamDomain::choices(std::vector<EnumLabel> l) {
  labels = std::move(l);
  return *this;
}

ParamDomain& ParamDomain::steps(double by, int shownDecimals) {
  step = by;
  decimals = shownDecimals;
  return *this;
}

ParamDomain& ParamDomain::in(std::string u) {
  unit = std::move(u);
  return *this;
}

ParamDomain& ParamDomain::offer(std::optional<double> lo, std::optional<double> hi) {
  uiMin = lo;
  uiMax = hi;
  return *this;
}

bool ParamDomain::contains(double v) const {
  if (min && (minExclusive ? v <= *min : v < *min)) return false;
  if (max && (maxExclusive ? v >= *max : v > *max)) return false;
  return true;
}

std::string ParamDomain::rangeText() const {
  using text::fmt;
  if (min && max && !minExclusive && !maxExclusive)
    return "lie in " + fmt(*min) + " ... " + fmt(*max);
  std::string out;
  if (min) out = (minExclusive ? "be greater than " : "be at least ") + fmt(*min);
  if (max)
    out += (out.empty() ? "be " : " and ") + std::string(maxExclusive ? "less than " : "at most ") +
           fmt(*max);
  return out.empty() ? "be a number" : out;
}

size_t labelIndex(const std::string& key, const std::vector<EnumLabel>& labels,
                  const std::string& text) {
  for (size_t i = 0; i < labels.size(); ++i) {
    const auto& aliases = labels[i].aliases;
    if (labels[i].name == text || std::find(aliases.begin(), aliases.end(), text) != aliases.end())
      return i;
  }
  throw inputError("--" + key + ": '" + text + "' is not one of " + labelNames(labels, ", "));
}

std::string labelNames(const std::vector<EnumLabel>& labels, const std::string& separator) {
  std::string out;
  for (const EnumLabel& l : labels) out += (out.empty() ? "" : separator) + l.name;
  return out;
}

double checkInDomain(const std::string& key, const ParamDomain& domain, double v,
                     const std::string& text) {
  if (!domain.contains(v))
    throw inputError("--" + key + ": must " + domain.rangeText() + ", got '" + text + "'");
  return v;
}

}  // namespace voxray
