// The enum name tables: every value's name parses back to it, unknown text is refused.
#include "core/named_values.h"

#include <gtest/gtest.h>

#include "core/ewa_footprint.h"
#include "core/post_classification.h"
#include "core/shear_warp_settings.h"
#include "core/splat_attributes.h"

namespace ewa {
namespace {

enum class Shade { Dark = 0, Light = 1, Grey = 7 };
constexpr NamedValue<Shade> kShades[] = {
    {Shade::Dark, "dark"}, {Shade::Light, "light"}, {Shade::Grey, "grey"}, {Shade::Grey, "gray"}};

TEST(NamedValues, NameAndParseUseOneTable) {
  EXPECT_STREQ(nameIn(kShades, Shade::Light), "light");
  EXPECT_STREQ(nameIn(kShades, Shade::Grey), "grey");  // the first name of a value is printed
  EXPECT_STREQ(nameIn(kShades, static_cast<Shade>(3)), "?");
  Shade s = Shade::Dark;
  EXPECT_TRUE(parseIn(kShades, "gray", &s));
  EXPECT_EQ(s, Shade::Grey);
  EXPECT_TRUE(parseIn(kShades, "light", &s));
  EXPECT_EQ(s, Shade::Light);
  // Case and surrounding text matter; a refused parse leaves the value as it was.
  for (const char* bad : {"Light", "light ", "", "lightx", "?"}) {
    EXPECT_FALSE(parseIn(kShades, bad, &s)) << bad;
    EXPECT_EQ(s, Shade::Light);
  }
}

// name(v) parses back to v for every value of the enums the command line and settings name.
template <typename E, typename Name, typename Parse>
void expectRoundTrip(std::initializer_list<E> values, Name name, Parse parse) {
  for (E v : values) {
    E parsed = *values.begin() == v ? *(values.end() - 1) : *values.begin();
    ASSERT_TRUE(parse(name(v), &parsed)) << name(v);
    EXPECT_EQ(parsed, v) << name(v);
    EXPECT_FALSE(parse(std::string(name(v)) + "x", &parsed));
  }
}

TEST(NamedValues, CoreEnumsRoundTrip) {
  expectRoundTrip({FilterMode::Ewa, FilterMode::Plain, FilterMode::Swan}, filterModeName,
                  parseFilterMode);
  expectRoundTrip({ClassificationMode::Pre, ClassificationMode::Post}, classificationModeName,
                  parseClassificationMode);
  expectRoundTrip({GradientMode::Central, GradientMode::Smooth}, gradientModeName,
                  parseGradientMode);
  expectRoundTrip({TableLookup::Nearest, TableLookup::Bilinear}, tableLookupName, parseTableLookup);
  expectRoundTrip({BufferSlices::Slice, BufferSlices::Image}, bufferSlicesName, parseBufferSlices);
  EXPECT_STREQ(filterModeName(FilterMode::Swan), "swan");
  EXPECT_STREQ(classificationModeName(ClassificationMode::Post), "post");
}

}  // namespace
}  // namespace ewa
