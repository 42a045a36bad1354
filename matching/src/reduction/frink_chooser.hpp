#pragma once
// The naive chooser: build H1 and test it for bridges from scratch, O(n) per reduction and O(n^2)
// in all (Frink's proof as stated, paper Appendix A). The oracle the fast choosers are tested
// against.

#include "reduction/chooser.hpp"

namespace petersen::reduction {

class FrinkChooser final : public Chooser {
 public:
  explicit FrinkChooser(std::uint32_t components) : components_(components) {}
  void remove(const ReductionGraph&, std::span<const EdgeId>) override {}
  bool choose_h1(const ReductionGraph& graph, const Step& step) override;
  void add(const ReductionGraph&, std::span<const EdgeId>) override {}

 private:
  std::uint32_t components_;
};

}  // namespace petersen::reduction
