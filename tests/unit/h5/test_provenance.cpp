#include <fstream>
#include <regex>

#include "hair/core/error.h"
#include "hair/core/version.h"
#include "hair/h5/attribute.h"
#include "hair/h5/file.h"
#include "hair/h5/provenance.h"
#include "unit/test_h5_support.h"

namespace hair {
namespace {

using ProvenanceTest = testing::TemporaryDirectoryTest;

class StageProvenanceTest : public testing::TemporaryDirectoryTest {
 protected:
  void SetUp() override {
    TemporaryDirectoryTest::SetUp();
    std::ofstream(path("bob.obj")) << "abc";
    std::ofstream(path("body.obj")) << "";
  }
  Provenance provenance(bool reproducible) {
    return stage_provenance("extract", R"({"unit_scale": 0.1, "min_points": 3})",
                            {{"hair_mesh", path("bob.obj")}, {"body_mesh", path("body.obj")}}, 1.25,
                            reproducible);
  }
};

TEST_F(StageProvenanceTest, DigestsInputsAndStampsTheRun) {
  const Provenance made = provenance(false);
  EXPECT_EQ(made.stage, "extract");
  EXPECT_EQ(made.project_version, project_version());
  ASSERT_EQ(made.inputs.size(), 2u);
  EXPECT_EQ(made.inputs[0],
            (ProvenanceInput{"hair_mesh", path("bob.obj").string(),
                             "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"}));
  EXPECT_EQ(made.wall_time_s, 1.25);
  ASSERT_TRUE(made.created_utc.has_value());
  EXPECT_TRUE(std::regex_match(*made.created_utc, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
      << *made.created_utc;
}

TEST_F(StageProvenanceTest, RoundTripsThroughRootAttributes) {
  const Provenance written = provenance(false);
  {
    h5::File file = h5::File::create(path("out.h5"));
    write_provenance(file, written);
    file.close();
  }
  const h5::File file = h5::File::open_read_only(path("out.h5"));
  EXPECT_EQ(read_provenance(file), written);
  EXPECT_EQ(h5::read_string_attribute(file, "/", "parameters"), written.parameters);
  EXPECT_EQ(
      h5::read_string_attribute(file, "/", "inputs").rfind(R"([{"role":"hair_mesh","path":)", 0),
      0u);
  const std::string text = format_provenance(written);
  EXPECT_NE(text.find("stage            extract"), std::string::npos) << text;
  EXPECT_NE(text.find("\"unit_scale\": 0.1"), std::string::npos) << text;  // pretty-printed
  EXPECT_NE(text.find("sha256 ba7816bf"), std::string::npos) << text;
}

TEST_F(StageProvenanceTest, ReproducibleRunsGiveIdenticalAttributes) {
  const auto write = [&](const std::string& name) {
    h5::File file = h5::File::create(path(name));
    write_provenance(file, provenance(true));
    file.close();
    return read_provenance(h5::File::open_read_only(path(name)));
  };
  const Provenance first = write("first.h5");
  const Provenance second = write("second.h5");
  EXPECT_EQ(first, second);
  EXPECT_FALSE(first.created_utc.has_value());
  EXPECT_FALSE(first.wall_time_s.has_value());
  const h5::File file = h5::File::open_read_only(path("first.h5"));
  EXPECT_FALSE(h5::has_attribute(file, "/", "created_utc"));
  EXPECT_FALSE(h5::has_attribute(file, "/", "wall_time_s"));
  EXPECT_NE(format_provenance(first).find("left out: reproducible run"), std::string::npos);
}

TEST_F(StageProvenanceTest, MissingInputIsBadInput) {
  EXPECT_THROW(stage_provenance("extract", "{}", {{"hair_mesh", path("absent.obj")}}, 0, true),
               Error);
}

TEST_F(ProvenanceTest, ParametersMustBeJson) {
  h5::File file = h5::File::create(path("out.h5"));
  Provenance bad;
  bad.stage = "extract";
  bad.parameters = "unit_scale = 0.1";
  EXPECT_THROW(write_provenance(file, bad), Error);
}

TEST_F(ProvenanceTest, MalformedInputsAreReported) {
  h5::File file = h5::File::create(path("out.h5"), "out.h5");
  Provenance without_inputs;
  without_inputs.stage = "extract";
  without_inputs.parameters = "{}";
  write_provenance(file, without_inputs);
  EXPECT_TRUE(read_provenance(file).inputs.empty());
  h5::write_string_attribute(file, "/", "inputs", R"([{"role": "mesh"}])");
  try {
    read_provenance(file);
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::bad_input);
    EXPECT_EQ(error.dataset(), "/@inputs");
  }
  H5Adelete(file.id(), "stage");
  EXPECT_THROW(read_provenance(file), Error);
}

}  // namespace
}  // namespace hair
