#include "solve/link_terms.h"

#include <gtest/gtest.h>

namespace microsim::sim::detail {
namespace {

// three nodes, an exponential wall link and a linear one
SpringModel twoLinks() {
  SpringModel model;
  model.addNode(Vec3(0.0, 0.0, 0.0));
  model.addNode(Vec3(0.1, 0.0, 0.0));
  model.addNode(Vec3(0.1, 0.15, 0.0));
  model.addLink(0, 1, 5.0, -1.0, StiffnessLaw::Exponential, 6.0);
  model.addLink(1, 2, 2.0);
  model.finalize();
  return model;
}

TEST(LinkTerms, GiveWhatThePlainKernelsGiveToTheBit) {
  const SpringModel model = twoLinks();
  Points x = model.restPositions();
  x.col(1) = Vec3(0.12, 0.01, 0.0);
  LinkTerms terms;
  terms.invalidate(model.linkCount());
  for (int li = 0; li < model.linkCount(); ++li) {
    const Link& link = model.link(li);
    EXPECT_EQ(terms.force(model, x, li), linkForce(link, x.col(link.a), x.col(link.b)));
    EXPECT_EQ(terms.energy(model, x, li), linkEnergy(link, x.col(link.a), x.col(link.b)));
    for (const bool clamp : {false, true}) {
      EXPECT_EQ(terms.hessian(model, x, li, link.b, link.a, clamp),
                linkHessian(link, x.col(link.b), x.col(link.a), clamp));
      EXPECT_EQ(terms.hessian(model, x, li, link.a, link.b, clamp),
                linkHessian(link, x.col(link.a), x.col(link.b), clamp));
    }
  }
}

TEST(LinkTerms, KeepTheirValuesUntilInvalidatedThenFollowTheNodes) {
  const SpringModel model = twoLinks();
  Points x = model.restPositions();
  LinkTerms terms;
  terms.invalidate(model.linkCount());
  EXPECT_EQ(terms.energy(model, x, 0), 0.0) << "at rest";
  x.col(1) = Vec3(0.13, 0.0, 0.0);
  EXPECT_EQ(terms.energy(model, x, 0), 0.0) << "the node moved, but nobody said so";
  terms.invalidate(model.linkCount());
  const Link& link = model.link(0);
  EXPECT_GT(terms.energy(model, x, 0), 0.0);
  EXPECT_EQ(terms.energy(model, x, 0), linkEnergy(link, x.col(0), x.col(1)));
}

TEST(LinkTerms, CoincidentEndsTakeThePlainKernels) {
  const SpringModel model = twoLinks();
  Points x = model.restPositions();
  x.col(1) = x.col(0);
  LinkTerms terms;
  terms.invalidate(model.linkCount());
  const Link& link = model.link(0);
  EXPECT_EQ(terms.force(model, x, 0), linkForce(link, x.col(0), x.col(1)));
  EXPECT_EQ(terms.energy(model, x, 0), linkEnergy(link, x.col(0), x.col(1)));
  EXPECT_EQ(terms.hessian(model, x, 0, 0, 1, false), linkHessian(link, x.col(0), x.col(1), false));
}

}  // namespace
}  // namespace microsim::sim::detail
