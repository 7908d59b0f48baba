// SPDX-License-Identifier: MIT
#include "bake/mesh_queries.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace frusta {

namespace {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5);
// Embree supplies the traversal, the primitive test is the caller's.
vec3 closest_on_triangle(const vec3& p, const vec3& a, const vec3& b, const vec3& c) {
  const vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// irrational-looking directions: no ray runs along an axis-aligned face or edge
const vec3 kVoteDirections[5] = {
    {0.5773502691896258, 0.5773502691896258, 0.5773502691896258},
    {-0.3120, 0.8815, -0.3543}, {0.7071, -0.1015, -0.6997},
    {-0.6401, -0.5236, 0.5622}, {0.1163, -0.9128, 0.3915}};

// a ray crossing more surfaces than this is in a pathological mesh; its count so far votes
constexpr int kMaxCrossings = 256;

// Embree asserts (and aborts the process) on a ray or query whose origin is not
// within +-1.8e18 in float; callers' points stay far inside this
constexpr double kEmbreeSafeCoordinate = 1e15;

bool embree_safe(const vec3& p) {
  return std::fabs(p.x) <= kEmbreeSafeCoordinate && std::fabs(p.y) <= kEmbreeSafeCoordinate &&
         std::fabs(p.z) <= kEmbreeSafeCoordinate;  // false for NaN too
}

}  // namespace

struct MeshQueries::Impl {
  const TriangleMesh* mesh = nullptr;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  vec3 lo{INFINITY}, hi{-INFINITY};  // of the vertices: nothing outside is inside

  struct Search {
    const TriangleMesh* mesh;
    vec3 point;
    double best = std::numeric_limits<double>::infinity();
    vec3 nearest{0.0};
  };

  static bool visit(RTCPointQueryFunctionArguments* args) {
    Search& s = *static_cast<Search*>(args->userPtr);
    const auto& t = s.mesh->triangles[args->primID];
    const vec3 q = closest_on_triangle(s.point, s.mesh->vertices[t[0]], s.mesh->vertices[t[1]],
                                       s.mesh->vertices[t[2]]);
    const double d = glm::length(q - s.point);
    if (d < s.best) {
      s.best = d;
      s.nearest = q;
      args->query->radius = static_cast<float>(d) * (1.0f + 1e-6f) + 1e-9f;  // shrink the search
      return true;
    }
    return false;
  }
};

frusta_result MeshQueries::create(const TriangleMesh& mesh, std::unique_ptr<MeshQueries>* out) {
  std::unique_ptr<MeshQueries> q(new MeshQueries());
  q->impl_ = std::make_unique<Impl>();
  Impl& m = *q->impl_;
  m.mesh = &mesh;
  for (const vec3& v : mesh.vertices) {
    m.lo = glm::min(m.lo, v);
    m.hi = glm::max(m.hi, v);
  }
  m.device = rtcNewDevice(nullptr);
  if (!m.device)
    return fail(FRUSTA_ERROR_INTERNAL, "Embree device creation failed (error %d)",
                static_cast<int>(rtcGetDeviceError(nullptr)));
  m.scene = rtcNewScene(m.device);
  rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree pads these buffers (it reads 16 bytes at the last float3)
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangles.size()));
  if (!vertices || !indices) {
    rtcReleaseGeometry(geometry);
    return fail(FRUSTA_ERROR_OUT_OF_MEMORY, "Embree could not allocate %zu vertices, %zu triangles",
                mesh.vertices.size(), mesh.triangles.size());
  }
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) vertices[3 * i + static_cast<size_t>(k)] = static_cast<float>(mesh.vertices[i][k]);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) indices[3 * t + static_cast<size_t>(k)] = mesh.triangles[t][k];
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(m.scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(m.scene);
  if (rtcGetDeviceError(m.device) != RTC_ERROR_NONE)
    return fail(FRUSTA_ERROR_INTERNAL, "Embree failed to build the BVH (error %d)",
                static_cast<int>(rtcGetDeviceError(m.device)));
  *out = std::move(q);
  return FRUSTA_OK;
}

MeshQueries::~MeshQueries() {
  if (!impl_) return;
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

MeshQueries::Closest MeshQueries::closest(const vec3& point, double max_distance) const {
  Impl::Search search{impl_->mesh, point};
  if (!embree_safe(point)) {
    // beyond what Embree accepts: every triangle, by hand (NaN finds nothing)
    const TriangleMesh& mesh = *impl_->mesh;
    for (const auto& t : mesh.triangles) {
      const vec3 q =
          closest_on_triangle(point, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
      const double d = glm::length(q - point);
      if (d < search.best && d <= max_distance) search.best = d, search.nearest = q;
    }
    return {search.best, search.nearest};
  }
  RTCPointQuery query;
  query.x = static_cast<float>(point.x);
  query.y = static_cast<float>(point.y);
  query.z = static_cast<float>(point.z);
  query.radius = static_cast<float>(max_distance);
  query.time = 0.0f;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &query, &context, &Impl::visit, &search);
  return {search.best, search.nearest};
}

bool MeshQueries::inside(const vec3& point) const {
  // outside the mesh's box (or NaN) is outside the solid; this also keeps every ray
  // origin where Embree accepts it
  const Impl& m = *impl_;
  if (!(point.x >= m.lo.x && point.x <= m.hi.x && point.y >= m.lo.y && point.y <= m.hi.y &&
        point.z >= m.lo.z && point.z <= m.hi.z))
    return false;
  int votes = 0;
  for (const vec3& d : kVoteDirections) {
    // winding number along the ray: +1 leaving a shell (back face), -1 entering one
    int winding = 0;
    float start = 0.0f;
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit hit{};
      hit.ray.org_x = static_cast<float>(point.x);
      hit.ray.org_y = static_cast<float>(point.y);
      hit.ray.org_z = static_cast<float>(point.z);
      hit.ray.dir_x = static_cast<float>(d.x);
      hit.ray.dir_y = static_cast<float>(d.y);
      hit.ray.dir_z = static_cast<float>(d.z);
      hit.ray.tnear = start;
      hit.ray.tfar = std::numeric_limits<float>::infinity();
      hit.ray.mask = 0xffffffffu;
      hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(impl_->scene, &context, &hit);
      if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
      // Ng = cross(v1 - v0, v2 - v0) points outwards
      const double facing = hit.hit.Ng_x * d.x + hit.hit.Ng_y * d.y + hit.hit.Ng_z * d.z;
      winding += facing > 0.0 ? 1 : -1;
      start = std::nextafter(hit.ray.tfar, std::numeric_limits<float>::infinity()) * (1.0f + 1e-6f);
    }
    votes += winding > 0;
  }
  return votes * 2 > static_cast<int>(std::size(kVoteDirections));
}

double MeshQueries::signed_distance(const vec3& point) const {
  const double d = closest(point).distance;
  return inside(point) ? -d : d;
}

}  // namespace frusta
