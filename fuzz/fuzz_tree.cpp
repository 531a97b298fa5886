// Fuzz target: the sphere-tree reader. The first byte picks the format (.sph, JSON, text or
// YAML), the rest is the file; a tree that is read must fill its layout exactly.
#include "fuzz_input.hpp"
#include "io/sphere_formats.hpp"
#include "sphereset/sphere_tree.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using sphereset::SphereFormat;
  using sphereset::fuzz::check;
  if (size == 0) return 0;
  const SphereFormat formats[] = {SphereFormat::kSph, SphereFormat::kJson, SphereFormat::kText,
                                  SphereFormat::kYaml};
  const SphereFormat format = formats[data[0] % 4];
  auto tree = sphereset::detail::parseSphereTree(
      format, sphereset::fuzz::asString(data + 1, size - 1), "fuzz");
  if (!tree) return 0;
  check(static_cast<int64_t>(tree->nodes.size()) ==
            sphereset::SphereTree::slotCount(tree->branching, tree->depth),
        "a tree read does not fill its layout");
  for (int l = 0; l <= tree->depth; ++l) (void)tree->level(l);
  return 0;
}
