// Each edge is clipped to the view, sampled every kSpacingPx on the image, and each
// sample asks how many surfaces a ray from the camera crosses before it; where the
// count changes between samples the change is found to a tenth of a pixel. Runs of
// hidden samples are joined at the joints their edges share, straightest first.
#include "core/npr/lines/hidden_lines.h"

#include "core/base/parallel.h"
#include "core/npr/lines/chain_shape.h"
#include "core/npr/lines/surface_edges.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <tuple>
#include <utility>

namespace inkray {
namespace {

constexpr float kSpacingPx = 1.5f;    // between samples along an edge on the image
constexpr int kRefineSteps = 4;       // halvings of a sample interval where the count changes
constexpr int kMostSurfaces = 64;     // a ray stops counting here
constexpr float kJoinDegrees = 50.f;  // where three or more runs meet, pairs turning less join
// Shorter chains are dropped: specks no stroke could draw, mostly where a faceted
// silhouette zig-zags just behind the surface beside it.
constexpr float kShortestPx = 2.f;
constexpr uint32_t kNoJoint = UINT32_MAX;

// Inside where dot(n, p - eye) >= offset.
struct Plane {
  Vec3 n{0.f};
  float offset = 0.f;
};

// What every sample reads: the camera at the frame and the image's edges in the world.
struct View {
  const RenderScene* scene = nullptr;
  Point3 eye{0.f};
  Vec3 forward{0.f, 0.f, -1.f};
  float time = 0.f;
  float width = 0.f, height = 0.f;
  float epsilon = 0.f;  // world units: surfaces this near a point lie on it, not in front
  std::array<Plane, 5> planes;
};

View make_view(const RenderScene& scene) {
  View v;
  v.scene = &scene;
  v.eye = scene.camera.origin();
  v.forward = scene.camera.forward();
  v.width = float(scene.sampling.width);
  v.height = float(scene.sampling.height);
  v.epsilon = 1e-5f * scene.world->scene_radius;
  // Through the lens's centre at the frame's instant: the pinhole.
  const Vec2 centre(0.5f);
  v.time = scene.camera.generate_ray(Vec2(0.f), centre).time;
  const std::array<Vec2, 4> corners = {Vec2(0.f), Vec2(v.width, 0.f), Vec2(v.width, v.height),
                                       Vec2(0.f, v.height)};
  for (size_t i = 0; i < 4; ++i) {
    Vec3 n = glm::cross(scene.camera.generate_ray(corners[i], centre).d,
                        scene.camera.generate_ray(corners[(i + 1) % 4], centre).d);
    if (glm::dot(n, v.forward) < 0.f) n = -n;
    v.planes[i] = {n, 0.f};
  }
  v.planes[4] = {v.forward, v.epsilon};
  return v;
}

// One point along an edge: where it is, and how many surfaces hide it.
struct Sample {
  float sigma = 0.f;  // position along the edge's visible part on the image, [0, 1]
  ChainPoint point;
  int covers = 0;
};

// Hits on the edge's own triangles (or a sphere's on itself) graze it and do not count.
bool own_hit(const SurfaceEdge& e, const Hit& h) {
  return h.geometry == e.object && (!e.own_object_hides || h.prim == e.faces[0] || h.prim == e.faces[1]);
}

// The surfaces between the camera and p, each counted once: the ray steps past every hit.
int count_covers(const View& view, const SurfaceEdge& e, const Point3& p, float distance) {
  if (!(distance > 0.f)) return 0;
  const Vec3 d = (p - view.eye) / distance;
  const float end = distance * (1.f - 1e-4f) - view.epsilon;
  const EmbreeScene& geometry = view.scene->world->geometry;
  int covers = 0;
  float from = 0.f;
  for (int step = 0; step < 2 * kMostSurfaces && covers < kMostSurfaces && from < end; ++step) {
    Hit h;
    if (!geometry.intersect_solid({view.eye + from * d, d, view.time}, end - from, &h)) break;
    if (!own_hit(e, h)) ++covers;
    const float reached = from + h.t;
    from = reached + std::max(view.epsilon, 1e-5f * reached);
  }
  return covers;
}

// The count at each joint, worked out by the first edge ending there that asks and
// shared with the others (most edges of a dense mesh are a sample or two long). At a
// joint the edge's own triangles meet the ray only at its end, which the ray stops
// short of, so the count is the same whichever edge asks.
class JointCovers {
 public:
  explicit JointCovers(uint32_t joints) : covers_(joints) {}
  int at(const View& view, const SurfaceEdge& e, uint32_t joint, const Point3& p, float distance) {
    std::atomic<int>& slot = covers_[joint];
    const int known = slot.load(std::memory_order_relaxed);
    if (known > 0) return known - 1;
    SurfaceEdge any_face = e;
    any_face.faces = {kNoFace, kNoFace};
    const int covers = count_covers(view, any_face, p, distance);
    slot.store(covers + 1, std::memory_order_relaxed);
    return covers;
  }

 private:
  std::vector<std::atomic<int>> covers_;  // covers + 1, 0 until known
};

// The part of an edge inside the view, the image's sides and a near plane, as a range
// of its parameter; false when none of it is.
bool clip_to_view(const View& view, const SurfaceEdge& e, float* s0, float* s1) {
  *s0 = 0.f, *s1 = 1.f;
  for (const Plane& plane : view.planes) {
    const float fa = glm::dot(plane.n, e.a - view.eye) - plane.offset;
    const float fb = glm::dot(plane.n, e.b - view.eye) - plane.offset;
    if (fa < 0.f && fb < 0.f) return false;
    if (fa < 0.f) *s0 = std::max(*s0, fa / (fa - fb));
    if (fb < 0.f) *s1 = std::min(*s1, fa / (fa - fb));
  }
  return *s0 < *s1;
}

// A stretch of one edge hidden behind the same number of surfaces.
struct Run {
  std::vector<ChainPoint> points;  // from the edge's end a towards b
  int covers = 0;
  LineType type = LineType::crease;
  uint32_t edge = 0;
  std::array<uint32_t, 2> joints{kNoJoint, kNoJoint};  // at its first and last point
};

void edge_runs(const View& view, const SurfaceEdge& e, uint32_t index, JointCovers& joints,
               std::vector<Run>& out) {
  float s0, s1;
  if (!clip_to_view(view, e, &s0, &s1)) return;
  const Point3 p0 = glm::mix(e.a, e.b, s0), p1 = glm::mix(e.a, e.b, s1);
  Vec2 f0, f1;
  const Camera& camera = view.scene->camera;
  if (!camera.project(p0, &f0) || !camera.project(p1, &f1)) return;
  const int n = std::clamp(int(std::ceil(glm::length(f1 - f0) / kSpacingPx)), 1, 1 << 16);
  // Evenly spaced on the image: the parameter along the edge in 3D at sigma, corrected
  // for perspective by the ends' depths.
  const float z0 = glm::dot(p0 - view.eye, view.forward), z1 = glm::dot(p1 - view.eye, view.forward);
  const bool whole_a = s0 == 0.f, whole_b = s1 == 1.f;  // the edge's own ends, its joints
  const auto sample = [&](float sigma) {
    const float t = sigma * z0 / ((1.f - sigma) * z1 + sigma * z0);
    const Point3 p = glm::mix(p0, p1, t);
    Sample at;
    at.sigma = sigma;
    Vec2 film = glm::mix(f0, f1, sigma);
    camera.project(p, &film);
    at.point.p = glm::clamp(film, Vec2(0.f), Vec2(view.width, view.height));
    at.point.depth = glm::length(p - view.eye);
    if (sigma == 0.f && whole_a)
      at.covers = joints.at(view, e, e.joint_a, p, at.point.depth);
    else if (sigma == 1.f && whole_b)
      at.covers = joints.at(view, e, e.joint_b, p, at.point.depth);
    else
      at.covers = count_covers(view, e, p, at.point.depth);
    return at;
  };
  std::vector<Sample> samples(size_t(n) + 1);
  for (int k = 0; k <= n; ++k) samples[size_t(k)] = sample(float(k) / float(n));
  // Where the count changes between k and k + 1: the last point of k's count and the
  // first of the other's.
  const auto refine = [&](int k) {
    Sample lo = samples[size_t(k)], hi = samples[size_t(k) + 1];
    for (int i = 0; i < kRefineSteps; ++i) {
      const Sample mid = sample(0.5f * (lo.sigma + hi.sigma));
      (mid.covers == lo.covers ? lo : hi) = mid;
    }
    return std::pair{lo, hi};
  };
  for (int k = 0; k <= n;) {
    const int covers = samples[size_t(k)].covers;
    int j = k;
    while (j < n && samples[size_t(j) + 1].covers == covers) ++j;
    if (covers >= 1) {
      Run run;
      run.covers = covers;
      run.type = e.type;
      run.edge = index;
      if (k > 0) run.points.push_back(refine(k - 1).second.point);
      for (int i = k; i <= j; ++i) run.points.push_back(samples[size_t(i)].point);
      if (j < n) run.points.push_back(refine(j).first.point);
      run.joints = {k == 0 && whole_a ? e.joint_a : kNoJoint, j == n && whole_b ? e.joint_b : kNoJoint};
      out.push_back(std::move(run));
    }
    k = j + 1;
  }
}

// The direction a run leaves its end `side` in, on the image.
Vec2 leaving(const Run& run, int side) {
  const auto& pts = run.points;
  const size_t n = pts.size();
  const Vec2 from = side == 0 ? pts.front().p : pts.back().p;
  Vec2 d(0.f);
  for (size_t i = 1; i < n; ++i) {
    d = (side == 0 ? pts[i].p : pts[n - 1 - i].p) - from;
    if (glm::length(d) >= 2.f * kSpacingPx) break;
  }
  const float len = glm::length(d);
  return len > 0.f ? d / len : d;
}

// Partner of each run end (2 * run + side), or -1: at a joint where two runs of the
// same type and count end they join; where more do, the pairs that turn least.
std::vector<int64_t> pair_ends(const std::vector<Run>& runs) {
  struct End {
    uint32_t joint;
    LineType type;
    int covers;
    uint32_t id;  // 2 * run + side
  };
  std::vector<End> ends;
  for (uint32_t r = 0; r < runs.size(); ++r)
    for (uint32_t side = 0; side < 2; ++side)
      if (runs[r].joints[side] != kNoJoint)
        ends.push_back({runs[r].joints[side], runs[r].type, runs[r].covers, 2 * r + side});
  const auto key = [](const End& e) { return std::tuple(e.joint, e.type, e.covers); };
  std::sort(ends.begin(), ends.end(),
            [&](const End& l, const End& r) { return key(l) != key(r) ? key(l) < key(r) : l.id < r.id; });
  std::vector<int64_t> partner(2 * runs.size(), -1);
  const auto join = [&](uint32_t a, uint32_t b) {
    if (a / 2 == b / 2 || partner[a] >= 0 || partner[b] >= 0) return;
    partner[a] = b, partner[b] = a;
  };
  for (size_t g = 0; g < ends.size();) {
    size_t end = g;
    while (end < ends.size() && key(ends[end]) == key(ends[g])) ++end;
    if (end - g == 2) {
      join(ends[g].id, ends[g + 1].id);
    } else if (end - g > 2) {
      struct Pair {
        float turn;
        uint32_t a, b;
      };
      std::vector<Pair> pairs;
      for (size_t i = g; i < end; ++i)
        for (size_t j = i + 1; j < end; ++j) {
          const Vec2 u = leaving(runs[ends[i].id / 2], int(ends[i].id % 2));
          const Vec2 v = leaving(runs[ends[j].id / 2], int(ends[j].id % 2));
          const float turn = glm::degrees(std::acos(std::clamp(-glm::dot(u, v), -1.f, 1.f)));
          if (turn < kJoinDegrees) pairs.push_back({turn, ends[i].id, ends[j].id});
        }
      std::sort(pairs.begin(), pairs.end(), [](const Pair& l, const Pair& r) {
        return std::tuple(l.turn, l.a, l.b) < std::tuple(r.turn, r.a, r.b);
      });
      for (const Pair& p : pairs) join(p.a, p.b);
    }
    g = end;
  }
  return partner;
}

void append(std::vector<ChainPoint>& to, const ChainPoint& q) {
  // Runs meeting at a joint both hold it; a refined end may repeat a sample.
  if (!to.empty() && glm::length(to.back().p - q.p) < 1e-3f) return;
  to.push_back(q);
}

// Follows joined runs from run r, entered at its end `side`, marking them used.
Chain follow(const std::vector<Run>& runs, const std::vector<int64_t>& partner, uint32_t r, int side,
             std::vector<bool>& used) {
  Chain c;
  c.type = runs[r].type;
  c.covers = runs[r].covers;
  const uint32_t start = r;
  const int start_side = side;
  for (;;) {
    used[r] = true;
    const auto& pts = runs[r].points;
    if (side == 0)
      for (const ChainPoint& q : pts) append(c.points, q);
    else
      for (auto q = pts.rbegin(); q != pts.rend(); ++q) append(c.points, *q);
    const int64_t next = partner[2 * r + uint32_t(1 - side)];
    if (next < 0) break;
    const uint32_t nr = uint32_t(next / 2);
    const int ns = int(next % 2);
    if (used[nr]) {
      c.closed = nr == start && ns == start_side;
      break;
    }
    r = nr, side = ns;
  }
  if (c.closed && c.points.size() > 1 && glm::length(c.points.back().p - c.points.front().p) < 1e-3f)
    c.points.pop_back();
  if (c.points.size() < 3) c.closed = false;
  return c;
}

}  // namespace

std::vector<Chain> hidden_chains(const RenderScene& scene, const Cancel& cancel) {
  std::vector<Chain> chains;
  if (scene.sampling.width <= 0 || scene.sampling.height <= 0 || cancel.requested()) return chains;
  const View view = make_view(scene);
  const SurfaceEdges found_edges = surface_edges(scene, view.eye, scene.lines.enabled, kSpacingPx);
  const std::vector<SurfaceEdge>& edges = found_edges.edges;
  JointCovers joints(found_edges.joints);
  std::vector<std::vector<Run>> per_edge(edges.size());
  parallel_for_chunks(
      edges.size(), 64,
      [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) edge_runs(view, edges[i], uint32_t(i), joints, per_edge[i]);
      },
      cancel);
  if (cancel.requested()) return chains;
  std::vector<Run> runs;
  for (auto& list : per_edge)
    for (Run& run : list) runs.push_back(std::move(run));
  per_edge = {};

  const std::vector<int64_t> partner = pair_ends(runs);
  std::vector<bool> used(runs.size(), false);
  std::vector<std::pair<Chain, uint32_t>> found;  // with the edge of its first run
  for (uint32_t r = 0; r < runs.size(); ++r) {
    if (used[r]) continue;
    if (partner[2 * r] < 0)
      found.emplace_back(follow(runs, partner, r, 0, used), runs[r].edge);
    else if (partner[2 * r + 1] < 0)
      found.emplace_back(follow(runs, partner, r, 1, used), runs[r].edge);
  }
  // What is left are loops.
  for (uint32_t r = 0; r < runs.size(); ++r)
    if (!used[r]) found.emplace_back(follow(runs, partner, r, 0, used), runs[r].edge);

  for (auto& [c, edge] : found) {
    if (c.points.size() < 2 || chain_length(c) < kShortestPx) continue;
    const RenderObject& object = scene.world->objects[edges[edge].object];
    c.path = LinePath::direct;
    c.object = int(object.source);
    c.material = int(object.material);
    orient_chain(c);
    measure_curvature(c);
    chains.push_back(std::move(c));
  }
  std::stable_sort(chains.begin(), chains.end(),
                   [](const Chain& l, const Chain& r) { return int(l.type) < int(r.type); });
  return chains;
}

}  // namespace inkray
