// SPDX-License-Identifier: MIT
// C ABI: single sphere/segment queries for bindings, tests and tools.
#include "capi/convert.h"
#include "core/error.h"
#include "core/validate.h"
#include "frusta/frusta.h"
#include "geometry/constraint.h"
#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "geometry/patent_test.h"

using namespace frusta;

namespace {

frusta_result read_inputs(const frusta_segment* segment, const frusta_sphere* sphere,
                          SegmentFrame* frame, Sphere* ball) {
  Segment s;
  if (frusta_result r = read_segment(segment, "segment", &s)) return r;
  if (frusta_result r = read_sphere(sphere, "sphere", ball)) return r;
  *frame = make_segment_frame(s);
  return FRUSTA_OK;
}

}  // namespace

FRUSTA_API frusta_result frusta_query_contact(const frusta_segment* segment,
                                              const frusta_sphere* sphere,
                                              frusta_contact_query* out) {
  SegmentFrame frame;
  Sphere ball;
  if (frusta_result r = read_inputs(segment, sphere, &frame, &ball)) return r;
  if (frusta_result r = check_out_struct(out, "out", "frusta_contact_query")) return r;
  const Proximity p = exact_proximity(frame, ball);
  out->feature = static_cast<int32_t>(p.feature);
  out->patent_contact = patent_contact(frame, ball) ? 1 : 0;
  out->contact = may_touch(frame, ball, 0.0) ? 1 : 0;
  out->distance = p.distance;
  store(p.hand_point, out->hand_point);
  store(p.object_point, out->object_point);
  store(p.normal, out->normal);
  out->axial = axial_fraction(frame, ball.center);
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_constraint_eval(const frusta_segment* segment,
                                                const frusta_sphere* sphere, int32_t form,
                                                frusta_constraint* out) {
  SegmentFrame frame;
  Sphere ball;
  if (frusta_result r = read_inputs(segment, sphere, &frame, &ball)) return r;
  if (form != FRUSTA_CONSTRAINT_SQUARED && form != FRUSTA_CONSTRAINT_DISTANCE)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "form is %d, must be FRUSTA_CONSTRAINT_SQUARED (0) or "
                "FRUSTA_CONSTRAINT_DISTANCE (1)", form);
  if (frusta_result r = check_out_struct(out, "out", "frusta_constraint")) return r;
  const Constraint c = contact_constraint(frame, ball, static_cast<ConstraintForm>(form));
  out->feature = static_cast<int32_t>(c.feature);
  out->value = c.value;
  store(c.grad_proximal, out->grad_proximal);
  store(c.grad_distal, out->grad_distal);
  store(c.grad_center, out->grad_center);
  return FRUSTA_OK;
}
