// docs/architecture.md shows the layering of the libraries; CMake generates it from the
// libraries it builds (build/layers.mmd). The two must be the same graph.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(LayersDoc, ArchitectureDocShowsTheGeneratedGraph) {
  const std::string generated = read(CORTEX_BUILD_DIR "/layers.mmd");
  const std::string doc = read(CORTEX_SOURCE_DIR "/docs/architecture.md");
  ASSERT_FALSE(generated.empty());
  const std::size_t start = doc.find("```mermaid\n");
  ASSERT_NE(start, std::string::npos) << "no mermaid block in docs/architecture.md";
  const std::size_t body = start + 11;
  const std::size_t end = doc.find("```", body);
  EXPECT_EQ(doc.substr(body, end - body), generated) << "update docs/architecture.md from build/layers.mmd";
}

}  // namespace
