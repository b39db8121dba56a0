// Parallel element loops (core/parallel.hpp): Q and the Newton matrix of a 200-element
// riser with Morison loads in current and waves and of an 8 x 8 plate are bit-identical
// for 1, 2 and 3 threads; the element colorings never put two elements that share a
// coordinate in one color.
#include "seaflex/core/parallel.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "seaflex/elements/ancf_beam.hpp"
#include "seaflex/elements/ancf_plate.hpp"
#include "seaflex/io/model_loader.hpp"

using namespace seaflex;

namespace {

// examples/riser_in_current.yaml with 200 elements, and an 8 x 8 plate beside it
io::Model riser_and_plate() {
  std::ifstream in(std::string(SEAFLEX_SOURCE_DIR) + "/examples/riser_in_current.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos)
      throw std::runtime_error(fmt::format("riser example changed: {}", from));
    text.replace(at, from.size(), to);
  };
  replace("elements: 20 ", "elements: 200 ");
  replace("bodies:\n", R"(bodies:
  plate:
    type: ancf_plate
    corner: [50, 0, -20]
    edge1: [10, 0, 0]
    edge2: [0, 10, 0]
    elements: [8, 8]
    thickness: 0.1
    youngs_modulus: 210e9
    poisson_ratio: 0.3
    density: 7950
)");
  return io::load_model_text(text, "riser_and_plate");
}

// a state away from the reference: every coordinate and velocity moved, within the waves'
// ramp (t = 20 s) so that the wave kinematics contribute
State perturbed(const System& system) {
  State s = system.initial_state();
  for (Index i = 0; i < s.q.size(); ++i) {
    s.q[i] += 1e-3 * std::sin(0.7 * static_cast<double>(i));
    s.v[i] = 0.2 * std::cos(1.3 * static_cast<double>(i));
  }
  s.t = 20.0;
  return s;
}

struct Evaluation {
  VecX Q;
  std::vector<double> values;  // the KKT matrix's value array
};

Evaluation evaluate_with(int threads, const System& system, const State& state) {
  set_threads(threads);
  DaeEval eval = system.make_eval();
  DaeRequest request;
  request.matrix = true;
  request.scales = {1.0, 0.3, 0.7};
  system.evaluate(state, request, eval);
  const SpMat& K = eval.kkt.matrix();
  return {eval.Q, std::vector<double>(K.valuePtr(), K.valuePtr() + K.nonZeros())};
}

bool same_bits(const double* a, const double* b, std::size_t n) {
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}

// within each color, no coordinate belongs to two elements
template <class Dofs>
void expect_colors_disjoint(const ElementColoring& coloring, int elements, Dofs dofs) {
  EXPECT_EQ(coloring.size(), elements);
  std::set<int> seen_elements;
  for (int c = 0; c < coloring.num_colors(); ++c) {
    std::set<Index> used;
    for (int el : coloring.color(c)) {
      EXPECT_TRUE(seen_elements.insert(el).second) << "element " << el << " twice";
      for (Index d : dofs(el))
        EXPECT_TRUE(used.insert(d).second) << "color " << c << " shares coordinate " << d;
    }
  }
  EXPECT_EQ(static_cast<int>(seen_elements.size()), elements);
}

class ParallelAssembly : public ::testing::Test {
 protected:
  void TearDown() override { set_threads(1); }
};

TEST_F(ParallelAssembly, BitIdenticalForOneTwoAndThreeThreads) {
  const io::Model model = riser_and_plate();
  const System& system = *model.system;
  const auto* riser = dynamic_cast<const AncfBeam*>(system.find_body("riser"));
  const auto* plate = dynamic_cast<const AncfPlate*>(system.find_body("plate"));
  ASSERT_NE(riser, nullptr);
  ASSERT_NE(plate, nullptr);
  // both take the parallel path
  EXPECT_EQ(riser->num_elements(), 200);
  EXPECT_GE(plate->num_elements(), kMinParallelElements);

  const State state = perturbed(system);
  const Evaluation one = evaluate_with(1, system, state);
  // not trivially zero: elastic forces, Morison loads, tangents all present
  EXPECT_GT(one.Q.segment(riser->offset(), riser->num_coordinates()).lpNorm<Eigen::Infinity>(),
            1e3);
  EXPECT_GT(one.Q.segment(plate->offset(), plate->num_coordinates()).lpNorm<Eigen::Infinity>(),
            1e3);
  ASSERT_TRUE(one.Q.allFinite());
  ASSERT_GT(one.values.size(), 100000u);
  std::size_t nonzero = 0;
  for (double x : one.values) nonzero += x != 0.0;
  EXPECT_GT(nonzero, one.values.size() / 2);

  for (int threads : {2, 3}) {
    const Evaluation other = evaluate_with(threads, system, state);
    EXPECT_EQ(seaflex::threads(), parallel_available() ? threads : 1);
    ASSERT_EQ(other.Q.size(), one.Q.size());
    ASSERT_EQ(other.values.size(), one.values.size());
    EXPECT_TRUE(same_bits(one.Q.data(), other.Q.data(), one.Q.size()))
        << "Q differs with " << threads << " threads";
    EXPECT_TRUE(same_bits(one.values.data(), other.values.data(), one.values.size()))
        << "matrix differs with " << threads << " threads";
  }
  // repeated evaluations on 2 threads: no leftover scratch
  const Evaluation again = evaluate_with(2, system, state);
  EXPECT_TRUE(same_bits(one.Q.data(), again.Q.data(), one.Q.size()));
  EXPECT_TRUE(same_bits(one.values.data(), again.values.data(), one.values.size()));
}

TEST_F(ParallelAssembly, ForcesOnlyBitIdentical) {
  // what an RK4 stage asks: forces and constraints, no matrix
  const io::Model model = riser_and_plate();
  const System& system = *model.system;
  const State state = perturbed(system);
  DaeEval a = system.make_eval(), b = system.make_eval();
  set_threads(1);
  system.evaluate(state, DaeRequest{}, a);
  set_threads(2);
  system.evaluate(state, DaeRequest{}, b);
  EXPECT_GT(a.Q.norm(), 0.0);
  EXPECT_TRUE(same_bits(a.Q.data(), b.Q.data(), a.Q.size()));
}

TEST_F(ParallelAssembly, ColorsShareNoCoordinate) {
  const io::Model model = riser_and_plate();
  const System& system = *model.system;
  const auto& riser = dynamic_cast<const AncfBeam&>(*system.find_body("riser"));
  const auto& plate = dynamic_cast<const AncfPlate&>(*system.find_body("plate"));
  EXPECT_EQ(riser.coloring().num_colors(), 2);
  expect_colors_disjoint(riser.coloring(), riser.num_elements(), [&](int el) {
    std::vector<Index> d;
    for (int i = 0; i < 12; ++i) d.push_back(riser.node_index(el) + i);
    return d;
  });
  EXPECT_EQ(plate.coloring().num_colors(), 4);
  expect_colors_disjoint(plate.coloring(), plate.num_elements(), [&](int el) {
    const auto& locals = plate.element_locals(el);
    return std::vector<Index>(locals.begin(), locals.end());
  });
}

TEST(ParallelSettings, ThreadCount) {
  EXPECT_THROW(
      {
        try {
          set_threads(0);
        } catch (const std::invalid_argument& e) {
          EXPECT_STREQ(e.what(), "set_threads: the thread count must be at least 1");
          throw;
        }
      },
      std::invalid_argument);
  set_threads(3);
  EXPECT_EQ(threads(), parallel_available() ? 3 : 1);
  set_threads(1);
  EXPECT_EQ(threads(), 1);
}

TEST(ParallelSettings, ColoringKeepsIndexOrderWithinAColor) {
  const std::vector<int> color = {1, 0, 1, 2, 0};
  const ElementColoring coloring(color);
  ASSERT_EQ(coloring.num_colors(), 3);
  EXPECT_EQ(std::vector<int>(coloring.color(0).begin(), coloring.color(0).end()),
            (std::vector<int>{1, 4}));
  EXPECT_EQ(std::vector<int>(coloring.color(1).begin(), coloring.color(1).end()),
            (std::vector<int>{0, 2}));
  EXPECT_EQ(std::vector<int>(coloring.color(2).begin(), coloring.color(2).end()),
            (std::vector<int>{3}));
}

TEST(ParallelSettings, ExceptionOfLowestElementLeavesTheLoop) {
  std::vector<int> color(200);
  for (int el = 0; el < 200; ++el) color[el] = el % 2;
  const ElementColoring coloring(color);
  for (int threads : {1, 2, 3}) {
    set_threads(threads);
    try {
      for_each_colored(coloring, [](int el) {
        if (el == 60 || el == 150) throw std::runtime_error(fmt::format("element {}", el));
      });
      ADD_FAILURE() << "no exception with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "element 60");
    }
  }
  set_threads(1);
}

}  // namespace
