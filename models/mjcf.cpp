#include "models/mjcf.h"

#include "sim/base/number_text.h"

namespace tactip::mjcf {

std::string Num(double v) {
  if (v == 0.0) return "0";  // also folds -0
  return RoundTripText(v);
}

Element& Element::Set(const std::string& name, const std::string& value) {
  for (auto& a : attrs_) {
    if (a.first == name) {
      a.second = value;
      return *this;
    }
  }
  attrs_.emplace_back(name, value);
  return *this;
}

Element& Element::Set(const std::string& name, double value) { return Set(name, Num(value)); }

Element& Element::SetInt(const std::string& name, long long value) { return Set(name, std::to_string(value)); }

Element& Element::Set(const std::string& name, const std::vector<double>& values) {
  std::string s;
  for (double v : values) s += (s.empty() ? "" : " ") + Num(v);
  return Set(name, s);
}

Element& Element::Add(std::string tag) {
  children_.emplace_back(std::move(tag));
  return children_.back();
}

Element& Element::Append(Element child) {
  children_.push_back(std::move(child));
  return children_.back();
}

Element& Element::Comment(std::string text) {
  comments_.push_back(std::move(text));
  return *this;
}

std::string Element::Get(const std::string& name) const {
  for (const auto& a : attrs_) {
    if (a.first == name) return a.second;
  }
  return {};
}

std::string Element::ToXml(int indent) const {
  const std::string pad(indent, ' ');
  std::string out = pad + "<" + tag_;
  for (const auto& [k, v] : attrs_) out += " " + k + "=\"" + v + "\"";
  if (children_.empty() && comments_.empty()) return out + "/>\n";
  out += ">\n";
  for (const auto& c : comments_) out += pad + "  <!-- " + c + " -->\n";
  for (const auto& c : children_) out += c.ToXml(indent + 2);
  return out + pad + "</" + tag_ + ">\n";
}

}  // namespace tactip::mjcf
