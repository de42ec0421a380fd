#pragma once
// A small MJCF (MuJoCo XML) element tree used by the model builders. Builders emit
// parts as Element trees; the scene assembler joins them and serialises to text.

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace tactip::mjcf {

/// One XML element with ordered attributes and children.
class Element {
 public:
  explicit Element(std::string tag) : tag_(std::move(tag)) {}

  /// Sets a text attribute; returns *this for chaining.
  Element& Set(const std::string& name, const std::string& value);
  /// Sets a numeric attribute, written with round-trip precision.
  Element& Set(const std::string& name, double value);
  /// Sets an integer attribute.
  Element& SetInt(const std::string& name, long long value);
  /// Sets a vector attribute ("x y z").
  Element& Set(const std::string& name, const std::vector<double>& values);
  Element& Set(const std::string& name, const std::array<double, 3>& v) {
    return Set(name, std::vector<double>(v.begin(), v.end()));
  }
  /// Appends a child element and returns a reference to it (valid until the next Add).
  Element& Add(std::string tag);
  /// Appends an existing element tree as a child.
  Element& Append(Element child);
  /// Adds an XML comment line before the children.
  Element& Comment(std::string text);

  const std::string& tag() const { return tag_; }
  std::vector<Element>& children() { return children_; }
  const std::vector<Element>& children() const { return children_; }
  /// The value of an attribute, or empty.
  std::string Get(const std::string& name) const;

  /// Serialises the tree with two-space indentation.
  std::string ToXml(int indent = 0) const;

 private:
  std::string tag_;
  std::vector<std::pair<std::string, std::string>> attrs_;
  std::vector<std::string> comments_;
  std::vector<Element> children_;
};

/// Formats a double with round-trip precision.
std::string Num(double v);

}  // namespace tactip::mjcf
