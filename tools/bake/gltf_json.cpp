// SPDX-License-Identifier: MIT
#include "gltf_json.h"

#include "gltf_loader.h"

namespace frusta {

namespace {

// Refuses JSON nested deeper than kMaxJsonDepth or with more than kMaxJsonValues
// values, as it goes: nlohmann's SAX parser keeps its own stack on the heap, so
// hostile nesting stops here instead of in tinygltf's recursion.
class BoundedJson {
 public:
  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(Json::number_integer_t) { return value(); }
  bool number_unsigned(Json::number_unsigned_t) { return value(); }
  bool number_float(Json::number_float_t, const Json::string_t&) { return value(); }
  bool string(Json::string_t&) { return value(); }
  bool binary(Json::binary_t&) { return value(); }
  bool key(Json::string_t& k) {
    if (depth_ == 1) top_key_ = k;  // names the member a refusal is in
    return value();
  }
  bool start_object(std::size_t) { return open(); }
  bool start_array(std::size_t) { return open(); }
  bool end_object() { return --depth_, true; }
  bool end_array() { return --depth_, true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
    why_ = e.what();
    return false;
  }
  const std::string& why() const { return why_; }

 private:
  bool value() {
    if (++values_ <= GltfLimits::kMaxJsonValues) return true;
    why_ = "more than " + std::to_string(GltfLimits::kMaxJsonValues) + " JSON values";
    return false;
  }
  bool open() {
    if (++depth_ > GltfLimits::kMaxJsonDepth) {
      why_ = "JSON nested more than " + std::to_string(GltfLimits::kMaxJsonDepth) +
             " levels deep (in \"" + top_key_.substr(0, 64) + "\")";
      return false;
    }
    return value();
  }
  int depth_ = 0;
  size_t values_ = 0;
  std::string top_key_, why_;
};

}  // namespace

bool parse_bounded_json(const char* text, size_t size, Json* out, std::string* why) {
  if (size > GltfLimits::kMaxJsonBytes) {
    *why = "its JSON is " + std::to_string(size) + " bytes, more than " +
           std::to_string(GltfLimits::kMaxJsonBytes);
    return false;
  }
  BoundedJson bounds;
  if (!Json::sax_parse(text, text + size, &bounds)) {
    *why = bounds.why();
    return false;
  }
  *out = Json::parse(text, text + size, nullptr, false);
  if (out->is_discarded()) {
    *why = "JSON the parser refused";  // the SAX pass accepted it: not expected
    return false;
  }
  return true;
}

}  // namespace frusta
