// The JSON-lines protocol: requests carry exactly the documented keys; replies that break the
// protocol are refused with a message saying what is wrong.
#include "comparisons/engines/outside/process_protocol.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tecido::outside {
namespace {

using io::Json;

std::string protocol_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const ProtocolError& e) {
    return e.what();
  }
  return "";
}

TEST(ProcessProtocol, Hello) {
  EXPECT_EQ(hello_request(), Json::parse(R"({"op":"hello","protocol":1})"));
  const Hello h = parse_hello(Json::parse(R"({"supports":["tri_tri","dynamics","future_op"],"order":2})"));
  EXPECT_EQ(h.supports.count("tri_tri"), 1u);
  EXPECT_EQ(h.supports.count("future_op"), 1u);  // kept, unused
  EXPECT_EQ(h.order, 2.0);
  EXPECT_FALSE(parse_hello(Json::parse(R"({"supports":["ccd"],"order":null})")).order);
  EXPECT_NE(protocol_error([] { parse_hello(Json::parse(R"({"order":2})")); }).find("lacks \"supports\""), std::string::npos);
  EXPECT_NE(protocol_error([] { parse_hello(Json::parse(R"({"supports":"tri_tri"})")); }).find("array of names"),
            std::string::npos);
  EXPECT_NE(protocol_error([] { parse_hello(Json::parse(R"({"supports":[],"order":-1})")); }).find("\"order\""),
            std::string::npos);
  EXPECT_NE(protocol_error([] { parse_hello(Json::parse(R"([1,2])")); }).find("expected a JSON object"), std::string::npos);
}

TEST(ProcessProtocol, HelloNamesTheProtocolItSpeaks) {
  EXPECT_EQ(parse_hello(Json::parse(R"({"protocol":1,"supports":["ccd"]})")).supports.count("ccd"), 1u);
  EXPECT_EQ(parse_hello(Json::parse(R"({"supports":["ccd"]})")).supports.count("ccd"), 1u);  // before the field: 1
  EXPECT_EQ(protocol_error([] { parse_hello(Json::parse(R"({"protocol":2,"supports":["ccd"]})")); }),
            "the engine speaks protocol 2, tecido speaks protocol 1 (\"protocol\" of the hello reply)");
  for (const char* other : {R"("1")", "1.5", "null", "[1]"})
    EXPECT_NE(protocol_error([&] { parse_hello(Json::parse(std::string(R"({"supports":["ccd"],"protocol":)") + other + "}")); })
                  .find("the engine speaks protocol " + Json::parse(other).dump()),
              std::string::npos)
        << other;
}

TEST(ProcessProtocol, TriTriRequestAndReply) {
  const TriTriQuery q{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {Vec3(0.5, 0.25, -1), Vec3(0, 0, 1), Vec3(1, 1, 1)}};
  EXPECT_EQ(with_op(tri_tri_query(q), "tri_tri"),
            Json::parse(R"({"op":"tri_tri","a":[[0,0,0],[1,0,0],[0,1,0]],"b":[[0.5,0.25,-1],[0,0,1],[1,1,1]]})"));
  EXPECT_EQ(parse_tri_tri(Json::parse(R"({"hit":true})")), true);
  EXPECT_EQ(parse_tri_tri(Json::parse(R"({"hit":false})")), false);
  EXPECT_FALSE(parse_tri_tri(Json::parse(R"({"hit":null})")).has_value());
  EXPECT_NE(protocol_error([] { parse_tri_tri(Json::parse(R"({"hit":1})")); }).find("true, false or null"),
            std::string::npos);
}

TEST(ProcessProtocol, CcdAndPlane) {
  CcdQuery q;
  q.kind = CcdKind::EdgeEdge;
  for (int i = 0; i < 4; ++i) q.x0[i] = Vec3(i, 0, 0), q.x1[i] = Vec3(i, 1, 0);
  const Json r = ccd_query(q);
  EXPECT_EQ(r["kind"], "edge-edge");
  EXPECT_EQ(r["t1"][3], Json::parse("[3,1,0]"));
  const auto hit = parse_ccd(Json::parse(R"({"hit":true,"toi":0.25})"));
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->hit);
  EXPECT_EQ(hit->toi, 0.25);
  EXPECT_FALSE(parse_ccd(Json::parse(R"({"hit":false,"toi":null})"))->hit);
  EXPECT_NE(protocol_error([] { parse_ccd(Json::parse(R"({"hit":true,"toi":null})")); }).find("\"toi\" must be a number"),
            std::string::npos);
  const auto p = parse_plane(Json::parse(R"({"hit":true,"t":0.5})"));
  EXPECT_TRUE(p->hit);
  EXPECT_EQ(p->t, 0.5);
}

TEST(ProcessProtocol, BatchMustAnswerEveryQuery) {
  EXPECT_EQ(parse_batch(Json::parse(R"({"results":[{"hit":true},{"hit":false}]})"), 2).size(), 2u);
  EXPECT_NE(protocol_error([] { parse_batch(Json::parse(R"({"results":[{"hit":true}]})"), 2); }).find("2 replies, got 1"),
            std::string::npos);
  EXPECT_NE(protocol_error([] { parse_batch(Json::parse(R"({"results":[true,false]})"), 2); }).find("object"),
            std::string::npos);
}

TEST(ProcessProtocol, CreateCarriesSceneAndFeatures) {
  Scene s;
  s.dt = 0.5;
  s.particles.add(Vec3(1, 2, 3), Vec3::Zero(), 2.0, 1.0, false);
  s.forces.wind = Wind{Vec3(1, 0, 0)};
  const Json r = create_request(s);
  EXPECT_EQ(r["op"], "create");
  EXPECT_EQ(r["scene"]["dt"], 0.5);
  EXPECT_EQ(r["scene"]["particles"][0]["mass"], 2.0);
  EXPECT_EQ(r["features"], Json::parse(R"(["wind"])"));
  EXPECT_FALSE(parse_create(Json::parse(R"({"ok":true})")));
  EXPECT_EQ(parse_create(Json::parse(R"({"error":"wind: not modelled"})")), "wind: not modelled");
  EXPECT_NE(protocol_error([] { parse_create(Json::parse(R"({"ok":false})")); }).find("expected {\"ok\":true}"),
            std::string::npos);
}

TEST(ProcessProtocol, StepState) {
  EXPECT_EQ(step_request(0.01, 100), Json::parse(R"({"op":"step","dt":0.01,"steps":100})"));
  const State s = parse_step(Json::parse(R"({"x":[[1,2,3],[4,null,6]],"v":[[0,0,0],[0,0,1]]})"), 2);
  EXPECT_EQ(s.x[0], Vec3(1, 2, 3));
  EXPECT_TRUE(std::isnan(s.x[1].y()));  // null: not finite
  EXPECT_EQ(s.v[1], Vec3(0, 0, 1));
  EXPECT_NE(protocol_error([] { parse_step(Json::parse(R"({"x":[[1,2,3]],"v":[[0,0,0]]})"), 2); }).find("2 points"),
            std::string::npos);
  EXPECT_NE(protocol_error([] { parse_step(Json::parse(R"({"x":[[1,2]],"v":[[0,0,0]]})"), 1); }).find("[x,y,z]"),
            std::string::npos);
  EXPECT_NE(protocol_error([] { parse_step(Json::parse(R"({"x":[[1,2,"a"]],"v":[[0,0,0]]})"), 1); }).find("holds"),
            std::string::npos);
}

}  // namespace
}  // namespace tecido::outside
