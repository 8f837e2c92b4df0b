// The colourings of a strands.h5 picture, as hair-render --color-by names them.

#include <gtest/gtest.h>

#include <string>

#include "hair/core/error.h"
#include "hair/render/grow_picture.h"

namespace hair {
namespace {

TEST(GrowPicture, ColouringsAreNamedAsTheCommandLineNamesThem) {
  EXPECT_EQ(parse_grown_colouring("cluster"), GrownColouring::cluster);
  EXPECT_EQ(parse_grown_colouring("root_cluster"), GrownColouring::root_cluster);
  EXPECT_EQ(parse_grown_colouring("rule"), GrownColouring::rule);
  EXPECT_EQ(parse_grown_colouring("direction"), GrownColouring::direction);
  try {
    parse_grown_colouring("style");
    ADD_FAILURE() << "accepted 'style'";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::usage);
    EXPECT_EQ(std::string(error.what()),
              "--color-by for strands.h5 is cluster, root_cluster, rule or direction, not 'style'");
  }
}

}  // namespace
}  // namespace hair
