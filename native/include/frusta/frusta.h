/* SPDX-License-Identifier: MIT */
/*
 * frusta.h — the one public header of Frusta, a contact-processing engine for
 * virtual-hand force interaction. Builds as C11 and as C++17.
 *
 * Conventions
 * - Units: metres, radians, newtons, seconds. Frames are right-handed.
 * - Every function returns a frusta_result (or a plain value documented as such).
 *   On failure the calling thread's frusta_last_error() names the field and value
 *   at fault, and nothing the call would have changed has changed, its outputs
 *   included.
 * - Names: free functions put the verb first (frusta_create_world,
 *   frusta_default_world_def); calls on an existing id put its noun first and take
 *   the id first (frusta_world_step, frusta_sphere_tree_save).
 * - One creation verb pair: whatever has an id is made by frusta_create_<thing> and
 *   ended by frusta_destroy_<thing>(id), which turns the id and every copy of it
 *   stale. A thing that lives in a world (frusta_create_object,
 *   frusta_create_world_hand, frusta_create_device) takes the world first, its id
 *   names that world (world0 != 0), and its destroy takes the id alone. A thing made
 *   from different sources names the source: frusta_create_sphere_tree_from_mesh,
 *   frusta_create_sphere_tree_from_file.
 * - Ids are small values passed by value. Zero-initialised means null
 *   (FRUSTA_ERROR_NULL_ID). An id whose thing was destroyed, that belongs to another
 *   world, or a standalone hand's id given to a world, is refused with
 *   FRUSTA_ERROR_STALE_ID naming it, never a crash.
 * - struct_size opens every def (an input; from the matching frusta_default_*_def(),
 *   whose hidden cookie catches hand-built ones) and every single struct a call fills
 *   (the caller sets struct_size first): a mismatch is FRUSTA_ERROR_STRUCT_SIZE.
 *   Elements of arrays have none: an array is counted in elements of this header.
 * - Output arrays: a call that copies an array takes (out, capacity, out_count). It
 *   sets *out_count to how many elements there are and writes the first
 *   min(capacity, *out_count) of them, FRUSTA_OK even when capacity is short (the
 *   caller sees *out_count > capacity and may ask again). out may be null only with
 *   capacity 0, which asks for the count alone; capacity < 0 is
 *   FRUSTA_ERROR_OUT_OF_RANGE; out_count may not be null (FRUSTA_ERROR_NULL_POINTER).
 * - Threads: each function's "Thread:" line names one of
 *     host  - the one thread that created the object the call acts on (a world, a
 *             standalone hand), e.g. a game's main thread; calls on one object from
 *             two host threads at once are not allowed;
 *     input - any one thread per world hand (a glove's), concurrently with the host;
 *     any   - any thread, concurrently.
 * - No C++ type, exception or abort crosses this header.
 * - Struct fields are fixed-width. An int32_t holding an enum names the enum first in
 *   its comment; a 0/1 flag's comment starts "1:" or "1 if". A double[3] is an
 *   (x, y, z) vector, a double[4] a unit quaternion (x, y, z, w). The C# binding is
 *   generated from this header by tools/bindings/generate_cs.py, which reads these.
 */
#ifndef FRUSTA_FRUSTA_H
#define FRUSTA_FRUSTA_H

#include <stdint.h>

#if defined(FRUSTA_BUILD)
#  if defined(_WIN32)
#    define FRUSTA_EXPORT __declspec(dllexport)
#  else
#    define FRUSTA_EXPORT __attribute__((visibility("default")))
#  endif
#elif defined(_WIN32) && defined(FRUSTA_DLL)
#  define FRUSTA_EXPORT __declspec(dllimport)
#else
#  define FRUSTA_EXPORT
#endif
#ifdef __cplusplus
#  define FRUSTA_API extern "C" FRUSTA_EXPORT
#else
#  define FRUSTA_API FRUSTA_EXPORT
#endif

/* ---------------------------------------------------------------- version */

/** This header's version, major.minor.patch: the major part. */
#define FRUSTA_VERSION_MAJOR 0
/** The minor part. */
#define FRUSTA_VERSION_MINOR 5
/** The patch part. */
#define FRUSTA_VERSION_PATCH 0
/** major*1000000 + minor*1000 + patch; frusta_version() returns the library's. */
#define FRUSTA_VERSION \
  (FRUSTA_VERSION_MAJOR * 1000000 + FRUSTA_VERSION_MINOR * 1000 + FRUSTA_VERSION_PATCH)
/** Bumped whenever a struct layout or a signature changes; see frusta_check_abi(). */
#define FRUSTA_ABI_VERSION 9

/** The library's FRUSTA_VERSION. Thread: any. */
FRUSTA_API int32_t frusta_version(void);
/** The library's FRUSTA_ABI_VERSION. Thread: any. */
FRUSTA_API int32_t frusta_abi_version(void);

/* ---------------------------------------------------------------- errors */

/* Shared with the engine's layers: native/src/core/base.h copies each FRUSTA_BASE_*
 * block (tools/bindings/generate_base.py; a test checks the copy). */
#ifndef FRUSTA_BASE_RESULT
#define FRUSTA_BASE_RESULT
/** What a call returns: FRUSTA_OK, or why it failed (frusta_last_error() says more). */
typedef enum frusta_result {
  FRUSTA_OK = 0,                     /* success */
  FRUSTA_ERROR_NULL_POINTER = 1,     /* a required pointer argument was null */
  FRUSTA_ERROR_STRUCT_SIZE = 2,      /* struct_size differs from this library's sizeof */
  FRUSTA_ERROR_DEF_NOT_DEFAULTED = 3,/* a def not obtained from frusta_default_*_def() */
  FRUSTA_ERROR_NULL_ID = 4,          /* a null id where an object is required */
  FRUSTA_ERROR_STALE_ID = 5,         /* the id's object was destroyed (or never existed) */
  FRUSTA_ERROR_NOT_FINITE = 6,       /* NaN or infinity in an input */
  FRUSTA_ERROR_OUT_OF_RANGE = 7,     /* a finite value outside its documented range */
  FRUSTA_ERROR_CAPACITY = 8,         /* a caller buffer or an internal pool is too small */
  FRUSTA_ERROR_ABI_MISMATCH = 9,     /* header and library disagree; see frusta_check_abi() */
  FRUSTA_ERROR_OUT_OF_MEMORY = 10,   /* the library ran out of memory */
  FRUSTA_ERROR_INTERNAL = 11,        /* a bug: please report frusta_last_error() */
  FRUSTA_ERROR_IO = 12,              /* a file could not be opened, read or written */
  FRUSTA_ERROR_FILE_FORMAT = 13,     /* not a Frusta file, or a format version we cannot read */
  FRUSTA_ERROR_CORRUPT_FILE = 14,    /* a Frusta file whose contents fail validation */
  FRUSTA_ERROR_WRONG_STATE = 15,     /* not now: e.g. stepping a world its own thread runs */
  FRUSTA_ERROR_UNAVAILABLE = 16,     /* a part this build lacks: the baker where Embree does not exist */
  FRUSTA_ERROR_CANCELLED = 17        /* a bake job stopped because it was asked to */
} frusta_result;
#endif /* FRUSTA_BASE_RESULT */

/** Message of the last failed call on this thread ("" after none). Valid until the
 *  next frusta call on this thread. Thread: any (the message is thread-local). */
FRUSTA_API const char* frusta_last_error(void);
/** Static name of a result code, e.g. "FRUSTA_ERROR_STALE_ID". Thread: any. */
FRUSTA_API const char* frusta_result_name(int32_t result);

/** Pass FRUSTA_ABI_VERSION: FRUSTA_OK when the library was built from a header with
 *  the same ABI, FRUSTA_ERROR_ABI_MISMATCH (with both versions in the message)
 *  otherwise. Bindings call this once before anything else. Thread: any. */
FRUSTA_API frusta_result frusta_check_abi(int32_t header_abi_version);
#define FRUSTA_CHECK_ABI() frusta_check_abi(FRUSTA_ABI_VERSION)

/** sizeof the public struct named `name` (e.g. "frusta_world_def") in this library, or
 *  0 for a name this library does not have. Bindings compare their mirrored layouts
 *  with it once at load. Thread: any. */
FRUSTA_API int32_t frusta_struct_size(const char* name);

/* ---------------------------------------------------------------- ids */

/** Hand handle, of a standalone hand (frusta_create_hand) or of a world's
 *  (frusta_create_world_hand). Opaque; pass by value. Zero-initialised means null. */
typedef struct frusta_hand_id {
  int32_t index1;      /* slot + 1 (a world's hand: its hand slot in the world + 1); 0 is null */
  uint16_t world0;     /* 0: standalone; else the owning world: slot + 1, and its
                          generation's low byte */
  uint16_t generation; /* bumped when the slot is reused */
} frusta_hand_id;
#define FRUSTA_IS_NULL(id) ((id).index1 == 0)

/* ---------------------------------------------------------------- math types */

/** A rigid pose: position in metres and a unit quaternion (x, y, z, w). */
typedef struct frusta_pose {
  double position[3];  /* metres */
  double rotation[4];  /* unit quaternion (x, y, z, w) */
} frusta_pose;

/** A sphere: centre in metres and radius in metres (>= 0). */
typedef struct frusta_sphere {
  double center[3];  /* metres */
  double radius;     /* metres, >= 0 */
} frusta_sphere;

/** One frustum segment of a finger with its end balls. The proximal end D carries
 *  the larger radius in a hand, but any radii >= 0 are valid. The segment solid is
 *  the frustum union a ball of proximal_radius at D and of distal_radius at E. */
typedef struct frusta_segment {
  double proximal[3];     /* D, metres */
  double distal[3];       /* E, metres */
  double proximal_radius; /* r1, metres */
  double distal_radius;   /* r2, metres */
} frusta_segment;

/* ---------------------------------------------------------------- hand */

#ifndef FRUSTA_BASE_HAND
#define FRUSTA_BASE_HAND
/** Which hand; a left hand mirrors a right one through the hand frame's x-z plane. */
typedef enum frusta_hand_side {
  FRUSTA_HAND_RIGHT = 0, /* a right hand (the default) */
  FRUSTA_HAND_LEFT = 1   /* a left hand */
} frusta_hand_side;
/** A finger, thumb first; it indexes every per-finger array. */
typedef enum frusta_finger {
  FRUSTA_FINGER_THUMB = 0,  /* its first segment is the metacarpal */
  FRUSTA_FINGER_INDEX = 1,  /* the index finger */
  FRUSTA_FINGER_MIDDLE = 2, /* the middle finger */
  FRUSTA_FINGER_RING = 3,   /* the ring finger */
  FRUSTA_FINGER_LITTLE = 4  /* the little finger */
} frusta_finger;

/** Fingers per hand, thumb first (frusta_finger). */
#define FRUSTA_FINGER_COUNT 5
/** Segments per finger, proximal to distal. */
#define FRUSTA_SEGMENTS_PER_FINGER 3
/** Per finger: abduction, then flexion of the first, second and third joint. */
#define FRUSTA_JOINTS_PER_FINGER 4
/** Segments per hand, finger-major. */
#define FRUSTA_HAND_SEGMENT_COUNT (FRUSTA_FINGER_COUNT * FRUSTA_SEGMENTS_PER_FINGER)
/** Joint angles per hand, finger-major. */
#define FRUSTA_HAND_JOINT_COUNT (FRUSTA_FINGER_COUNT * FRUSTA_JOINTS_PER_FINGER)
/** The largest |joint angle| any input may carry, radians (4 pi): beyond it a reading
 *  is corrupt and refused; within it, angles beyond the hand's limits are clamped. */
#define FRUSTA_MAX_JOINT_ANGLE 12.566370614359172
/** Palm pose degrees of freedom in a Jacobian: translation x y z, then rotation x y z. */
#define FRUSTA_PALM_DOF 6
#endif /* FRUSTA_BASE_HAND */

/** Creation parameters of a hand.
 *
 *  Hand frame (right hand): origin at the wrist centre, +x towards the fingertips,
 *  +z out of the back of the hand, +y = z cross x (towards the thumb). A left hand
 *  is the mirror image through the x-z plane: its thumb lies at -y, and the same
 *  joint angles mean the same anatomical motion on both hands.
 *
 *  Joint angles: abduction rotates a finger about its rest frame's z towards the
 *  thumb side (radial); flexion rotates about its y towards the palm. The thumb's
 *  first segment is its metacarpal (joints CMC, MCP, IP); the other fingers' first
 *  segment is the proximal phalanx (joints MCP, PIP, DIP).
 *
 *  frusta_default_hand_def() fills every array from hand_length and hand_breadth
 *  (see frusta_hand_def_set_size); edit single entries afterwards to override.
 *  Ranges: hand_length and hand_breadth 0.01..5 m; every segment length, joint radius
 *  and palm dimension 1e-4..5 m, with at most 4096 palm spheres (the palm's thickness
 *  sets their spacing); base positions within 5 m, base rotations within 2 pi; joint
 *  limits within [-pi, pi], joint_min <= joint_max. */
typedef struct frusta_hand_def {
  int32_t struct_size;            /* sizeof(frusta_hand_def) */
  int32_t side;                   /* frusta_hand_side */
  double hand_length;             /* metres, wrist crease to middle fingertip */
  double hand_breadth;            /* metres, across the metacarpal heads */
  /* metres, joint centre to joint centre; the third runs to the tip hemisphere's centre */
  double segment_length[FRUSTA_FINGER_COUNT][FRUSTA_SEGMENTS_PER_FINGER];
  /* metres: ball radius at the first, second, third joint, then the tip hemisphere */
  double joint_radius[FRUSTA_FINGER_COUNT][4];
  double base_position[FRUSTA_FINGER_COUNT][3];  /* metres, first joint centre in the hand frame */
  double base_rotation[FRUSTA_FINGER_COUNT][3];  /* radians, x-y-z rotation of the rest frame */
  double joint_min[FRUSTA_FINGER_COUNT][FRUSTA_JOINTS_PER_FINGER]; /* radians */
  double joint_max[FRUSTA_FINGER_COUNT][FRUSTA_JOINTS_PER_FINGER]; /* radians */
  double palm_length;             /* metres, wrist to the metacarpal heads */
  double palm_breadth;            /* metres */
  double palm_thickness;          /* metres; also the palm spheres' diameter */
  int32_t internal_value;         /* set by frusta_default_hand_def(); do not touch */
  int32_t reserved0;              /* explicit padding */
} frusta_hand_def;

/** A right hand of 50th-percentile adult size (length 0.19 m, breadth 0.085 m).
 *  Thread: any. */
FRUSTA_API frusta_hand_def frusta_default_hand_def(void);

/** Refill def's geometry (segment lengths, joint radii, bases, palm) from a hand
 *  length and breadth with the anthropometric proportions documented in
 *  native/src/hand/anthropometry.cpp (each 0.01..5 m). Sizes whose proportions give
 *  a part outside the def's ranges (a hand of a few centimetres, or one far broader
 *  than long) are refused with FRUSTA_ERROR_OUT_OF_RANGE naming both sizes and the
 *  part. Joint limits and side are kept. On error def is unchanged. Thread: any. */
FRUSTA_API frusta_result frusta_hand_def_set_size(frusta_hand_def* def, double hand_length,
                                                  double hand_breadth);

/** Create a standalone hand at the identity pose with all joint angles zero (clamped
 *  into the limits), for queries outside a world (a world's hands come from
 *  frusta_create_world_hand). Thread: any (creation and destruction are serialised
 *  internally); the calling thread is the hand's host. */
FRUSTA_API frusta_result frusta_create_hand(const frusta_hand_def* def, frusta_hand_id* out_hand);
/** Destroy a standalone hand; its id and every copy of it become stale. A world's hand
 *  is refused (FRUSTA_ERROR_STALE_ID): frusta_destroy_world_hand destroys it.
 *  Thread: host. */
FRUSTA_API frusta_result frusta_destroy_hand(frusta_hand_id hand);
/** 1 if the id names a live hand, standalone or in a live world, else 0 (never an
 *  error). Thread: any. */
FRUSTA_API int32_t frusta_hand_is_valid(frusta_hand_id hand);

/* The frusta_hand_* calls below act on standalone hands: a world's hand id is refused
 * with FRUSTA_ERROR_STALE_ID (its state is the world's: frusta_world_get_hand). */

/** Set the palm pose (hand frame in world). The quaternion is normalised; its norm
 *  must lie in [0.5, 2] and positions within 1e6 m of the origin. Thread: host. */
FRUSTA_API frusta_result frusta_hand_set_palm_pose(frusta_hand_id hand, const frusta_pose* pose);
/** Set all FRUSTA_HAND_JOINT_COUNT joint angles (finger-major: abduction, flexion 1,
 *  2, 3), radians. |angle| <= FRUSTA_MAX_JOINT_ANGLE is accepted and clamped into the
 *  def's limits; beyond it, or not finite, the call is refused as corrupt input.
 *  count must equal FRUSTA_HAND_JOINT_COUNT. Thread: host. */
FRUSTA_API frusta_result frusta_hand_set_joint_angles(frusta_hand_id hand, const double* angles,
                                                      int32_t count);
/** Copy the (clamped) joint angles, radians, finger-major: FRUSTA_HAND_JOINT_COUNT
 *  of them, by the output-array rule (out null only with capacity 0). Thread: host. */
FRUSTA_API frusta_result frusta_hand_get_joint_angles(frusta_hand_id hand, double* out,
                                                      int32_t capacity, int32_t* out_count);
/** Copy the world geometry of every finger segment, finger-major (thumb first),
 *  proximal to distal: FRUSTA_HAND_SEGMENT_COUNT of them, by the output-array rule.
 *  The last segment of each finger has its tip hemisphere at the distal end.
 *  Thread: host. */
FRUSTA_API frusta_result frusta_hand_get_segments(frusta_hand_id hand, frusta_segment* out,
                                                  int32_t capacity, int32_t* out_count);
/** Copy the palm's spheres in world coordinates, by the output-array rule (capacity
 *  0 and out null ask for the count). Thread: host. */
FRUSTA_API frusta_result frusta_hand_get_palm_spheres(frusta_hand_id hand, frusta_sphere* out,
                                                      int32_t capacity, int32_t* out_count);
/** Doubles in one point Jacobian: 3 rows x (4 joint angles + 6 palm DOF) = 30. */
#define FRUSTA_POINT_JACOBIAN_LENGTH (3 * (FRUSTA_JOINTS_PER_FINGER + FRUSTA_PALM_DOF))
/** Jacobian of a material point of one segment, in world coordinates (metres per
 *  radian, and per metre or radian of the palm), with respect to the finger's four
 *  joint angles followed by the palm's 6 DOF (world translation, then a world-frame
 *  rotation vector): row-major 3 x 10, FRUSTA_POINT_JACOBIAN_LENGTH doubles copied to
 *  out_jacobian by the output-array rule. The point is given in metres in the segment
 *  frame: origin at the proximal joint, +x along the segment, y and z as the finger's
 *  flexion and its normal. Also writes the point's world position, metres, to
 *  out_point (may be null). Thread: host. */
FRUSTA_API frusta_result frusta_hand_point_jacobian(frusta_hand_id hand, int32_t finger,
                                                    int32_t segment, const double local_point[3],
                                                    double* out_point, double* out_jacobian,
                                                    int32_t capacity, int32_t* out_count);

/* ---------------------------------------------------------------- tracked hands
 * Hand tracking (OpenXR's XR_EXT_hand_tracking, Unity's XR Hands, camera trackers)
 * reports joints, not angles. A hand fitter turns one sample of tracked joints into
 * what a world hand takes (frusta_world_set_haptic): the palm pose and the
 * FRUSTA_HAND_JOINT_COUNT joint angles of a given hand def, clamped into its limits,
 * with a residual per finger. Two layouts (frusta_joint_layout):
 *
 *   FRUSTA_JOINT_LAYOUT_XR (26 joints, XrHandJointEXT's order): 0 palm, 1 wrist,
 *     2..5 thumb metacarpal, proximal, distal, tip, then index, middle, ring, little
 *     (6.., 11.., 16.., 21..) each metacarpal, proximal, intermediate, distal, tip.
 *     Each joint a pose with OpenXR's axes: -Z along the bone that starts at the
 *     joint, towards the tip (a tip: along the last bone); +Y out of the back of the
 *     finger (of the hand, for palm, wrist and metacarpals); X = Y cross Z.
 *   FRUSTA_JOINT_LAYOUT_KEYPOINTS (21 positions, MediaPipe's and MANO's order):
 *     0 wrist, 1..4 thumb CMC, MCP, IP, tip, then index, middle, ring, little
 *     (5.., 9.., 13.., 17..) each MCP, PIP, DIP, tip. Orientations are ignored.
 *
 * Where the joints sit on a Frusta hand (frusta_hand_def's hand frame; a left hand
 * mirrors y): the thumb's chain CMC, MCP, IP, tip is XR's thumb metacarpal, proximal,
 * distal, tip; a finger's MCP, PIP, DIP, tip is XR's proximal, intermediate, distal,
 * tip; a chain joint is the centre of its joint ball (first joint: base_position), and
 * a tip is the fingertip's end: the tip hemisphere's centre plus its radius along the
 * last segment. Palm-rigid joints: the wrist at the hand frame's origin with the hand
 * frame's axes (-Z = +x, +Y = +z); a finger's metacarpal joint (its carpometacarpal
 * joint) on the line from the wrist to its MCP joint, 0.4 of the way, oriented along
 * that line with +Y nearest +z; the palm at the middle of the middle finger's
 * metacarpal, oriented as it. A joint's radius: its ball's (metacarpal: the MCP
 * ball's; palm and wrist: half the palm's thickness). frusta_hand_joints_from_pose
 * makes exactly these joints, and a fitter fits them back exactly.
 *
 * The fit: the palm is the weighted least-squares rigid fit of the palm-rigid joints
 * present (XR: palm, wrist, the metacarpals, the thumb's metacarpal and the fingers'
 * proximal joints; keypoints: wrist, thumb CMC and the four MCPs), their orientations
 * joining in by def.orientation_weight, and alone when fewer than three points that are
 * not in a line are present. Each finger is then fit to its moving joints (XR:
 * proximal..tip of the thumb, intermediate..tip of the others; keypoints: MCP..tip of
 * the thumb, PIP..tip of the others) by an analytic guess refined by damped
 * Gauss-Newton steps within the joint limits. A joint counts when its flags have
 * FRUSTA_JOINT_POSITION_VALID (and FRUSTA_JOINT_POSITION_TRACKED with
 * def.require_tracked). What too few joints determine keeps its last good value and
 * says so (frusta_fit_flag): a finger needs two moving joints; the angles beyond its
 * last present joint are kept; a held palm holds every finger.
 */

#ifndef FRUSTA_BASE_TRACKING
#define FRUSTA_BASE_TRACKING
/** Joints of FRUSTA_JOINT_LAYOUT_XR: OpenXR's XR_HAND_JOINT_COUNT_EXT. */
#define FRUSTA_XR_JOINT_COUNT 26
/** Joints of FRUSTA_JOINT_LAYOUT_KEYPOINTS. */
#define FRUSTA_KEYPOINT_COUNT 21
/** How tracked joints are laid out (see the section's comment). */
typedef enum frusta_joint_layout {
  FRUSTA_JOINT_LAYOUT_XR = 0,       /* OpenXR's 26 joint poses, XrHandJointEXT order */
  FRUSTA_JOINT_LAYOUT_KEYPOINTS = 1 /* 21 keypoint positions, MediaPipe/MANO order */
} frusta_joint_layout;
/** What a tracked joint's fields hold: bits of frusta_tracked_joint.flags, with the
 *  values of OpenXR's XrSpaceLocationFlags (pass xrLocateHandJointsEXT's locationFlags
 *  as they are). */
typedef enum frusta_joint_flag {
  FRUSTA_JOINT_ORIENTATION_VALID = 1,   /* rotation holds a pose */
  FRUSTA_JOINT_POSITION_VALID = 2,      /* position holds a position */
  FRUSTA_JOINT_ORIENTATION_TRACKED = 4, /* rotation is tracked, not inferred */
  FRUSTA_JOINT_POSITION_TRACKED = 8     /* position is tracked, not inferred */
} frusta_joint_flag;
/** How a fit came about: bits of frusta_hand_fit.palm_flags and finger_flags. */
typedef enum frusta_fit_flag {
  FRUSTA_FIT_HELD = 1,        /* too few joints present: the last good value is given (a
                                 finger's too when the palm is held) */
  FRUSTA_FIT_PARTIAL = 2,     /* a finger's angles beyond its last present joint kept their
                                 last good values */
  FRUSTA_FIT_CLAMPED = 4,     /* a joint limit stopped an angle the joints ask beyond */
  FRUSTA_FIT_NO_HISTORY = 8,  /* held before any good fit: the rest pose, at the joints'
                                 origin; do not drive a hand with it */
  FRUSTA_FIT_ORIENTATION = 16 /* the palm's rotation came from joint orientations alone:
                                 fewer than three points out of line were present */
} frusta_fit_flag;
#endif /* FRUSTA_BASE_TRACKING */

/** One tracked joint, in any frame (the fit's palm is in that frame, composed with the
 *  frame pose given to the fit). Fields a flag does not declare valid are ignored and
 *  may hold anything; valid ones must be finite, positions within 1e6 m, quaternion
 *  norms in [0.5, 2] (normalised), radius 0..5 m. */
typedef struct frusta_tracked_joint {
  double position[3];  /* metres */
  double rotation[4];  /* unit quaternion (x, y, z, w), OpenXR's joint axes */
  double radius;       /* metres, 0 when unknown (the fit does not use it) */
  int32_t flags;       /* frusta_joint_flag bits */
  int32_t reserved0;   /* explicit padding */
} frusta_tracked_joint;

/** Hand fitter handle. Opaque; pass by value; zero means null. */
typedef struct frusta_hand_fitter_id {
  int32_t index1;      /* slot + 1; 0 is null */
  uint16_t world0;     /* always 0: fitters are standalone */
  uint16_t generation; /* bumped when the slot is reused */
} frusta_hand_fitter_id;

/** How a fitter reads joints; from frusta_default_hand_fit_def(). */
typedef struct frusta_hand_fit_def {
  int32_t struct_size;        /* sizeof(frusta_hand_fit_def) */
  int32_t layout;             /* frusta_joint_layout of the joints; default
                                 FRUSTA_JOINT_LAYOUT_XR */
  int32_t require_tracked;    /* 1: a joint whose position is valid but not tracked
                                 (inferred by the runtime) counts as missing; default 0 */
  int32_t max_iterations;     /* damped Gauss-Newton steps per finger, 1..100; default 10 */
  double orientation_weight;  /* metres, 0..1: each palm-rigid joint orientation weighs in
                                 the palm's fit like points this far from it; 0 (default):
                                 orientations are used only when fewer than three points
                                 out of line are present */
  double filter_min_cutoff;   /* Hz, 0..1000: the One Euro filter (Casiez et al., CHI 2012)
                                 frusta_hand_fitter_fit_at applies to the palm position,
                                 the palm rotation and each angle: its cutoff at rest. 0:
                                 no filter, fits bit-identical to unfiltered ones; default
                                 1 (measured: README, tracked hands) */
  double filter_beta;         /* 1/m (Hz per m/s), 0..1000: the cutoff rises to min_cutoff
                                 + beta * speed, so fast motion lags little; a rotation's
                                 or an angle's rad/s count as the speed of a point 0.1 m
                                 from its axis; default 2 */
  double filter_d_cutoff;     /* Hz, 0.001..1000: the cutoff of the speed's own low-pass;
                                 default 1 */
  int32_t internal_value;     /* set by frusta_default_hand_fit_def(); do not touch */
  int32_t reserved0;          /* explicit padding */
} frusta_hand_fit_def;

/** One fit: what frusta_world_set_haptic takes (palm, angles), and how good it is. */
typedef struct frusta_hand_fit {
  int32_t struct_size;        /* sizeof(frusta_hand_fit); set it before the call */
  int32_t palm_flags;         /* frusta_fit_flag bits of the palm */
  frusta_pose palm;           /* the hand frame: in the joints' frame, composed with the
                                 frame pose given to the fit (metres) */
  double angles[FRUSTA_HAND_JOINT_COUNT]; /* radians, finger-major, within the limits */
  double palm_residual;       /* metres: RMS distance of the palm-rigid joints present from
                                 the fitted hand's (0 when none is) */
  double finger_residual[FRUSTA_FINGER_COUNT]; /* metres: the same over each finger's
                                 moving joints */
  int32_t finger_flags[FRUSTA_FINGER_COUNT];   /* frusta_fit_flag bits of each finger */
  int32_t reserved0;          /* explicit padding */
} frusta_hand_fit;

/** Defaults for frusta_create_hand_fitter. Thread: any. */
FRUSTA_API frusta_hand_fit_def frusta_default_hand_fit_def(void);
/** Create a fitter for a hand of def (its side, sizes and limits: calibrate the def
 *  first, frusta_calibrate_hand_def, for a close fit) reading joints as fit_def says.
 *  It starts with no history (FRUSTA_FIT_NO_HISTORY). Thread: any; the calling thread
 *  is the fitter's host. */
FRUSTA_API frusta_result frusta_create_hand_fitter(const frusta_hand_def* def,
                                                   const frusta_hand_fit_def* fit_def,
                                                   frusta_hand_fitter_id* out_fitter);
/** Destroy a fitter; its id and every copy of it become stale. Thread: host. */
FRUSTA_API frusta_result frusta_destroy_hand_fitter(frusta_hand_fitter_id fitter);
/** 1 if the id names a live fitter, else 0 (never an error). Thread: any. */
FRUSTA_API int32_t frusta_hand_fitter_is_valid(frusta_hand_fitter_id fitter);
/** Fit one sample: count joints of the fitter's layout (FRUSTA_XR_JOINT_COUNT or
 *  FRUSTA_KEYPOINT_COUNT), in a frame whose pose in the world is frame (null: the
 *  identity; e.g. the XR tracking origin), into out (set out->struct_size first). Feed
 *  out->palm and out->angles to frusta_world_set_haptic. Joints breaking the rules of
 *  frusta_tracked_joint are refused, naming the joint and field, and change nothing;
 *  missing ones are not an error (see frusta_fit_flag). Allocation-free, microseconds.
 *  Thread: host. */
FRUSTA_API frusta_result frusta_hand_fitter_fit(frusta_hand_fitter_id fitter,
                                                const frusta_tracked_joint* joints,
                                                int32_t count, const frusta_pose* frame,
                                                frusta_hand_fit* out);
/** frusta_hand_fitter_fit of a sample taken at time (seconds, any origin, finite and
 *  strictly after the previous timed sample's; otherwise refused naming "time", nothing
 *  changed), through the fitter's One Euro filter (frusta_hand_fit_def.filter_*): the
 *  palm position, palm rotation and angles are filtered in the joints' frame, then
 *  composed with frame; residuals and flags are the unfiltered fit's. At rest the filter
 *  is a first-order low-pass of filter_min_cutoff: a step is followed to 63 % after
 *  1 / (2 pi filter_min_cutoff) s; moving, the cutoff rises with the speed. A held palm
 *  (FRUSTA_FIT_HELD, tracking lost) restarts the whole filter, a held finger its angles:
 *  the next fit is taken as it is, not dragged from a stale pose. An untimed
 *  frusta_hand_fitter_fit is unfiltered and restarts the filter (the next timed sample
 *  may then have any time). With filter_min_cutoff 0 the result is bit-identical to
 *  frusta_hand_fitter_fit's. Allocation-free. Thread: host. */
FRUSTA_API frusta_result frusta_hand_fitter_fit_at(frusta_hand_fitter_id fitter, double time,
                                                   const frusta_tracked_joint* joints,
                                                   int32_t count, const frusta_pose* frame,
                                                   frusta_hand_fit* out);
/** The joints of a layout on a hand of def at a palm pose (metres) with
 *  FRUSTA_HAND_JOINT_COUNT joint angles (radians; clamped into the limits as
 *  frusta_hand_set_joint_angles does), every flag set, by the output-array rule: what a
 *  tracker would report for that hand (tests, recordings, demos). Thread: any. */
FRUSTA_API frusta_result frusta_hand_joints_from_pose(const frusta_hand_def* def, int32_t layout,
                                                      const frusta_pose* palm,
                                                      const double* angles, int32_t angle_count,
                                                      frusta_tracked_joint* out, int32_t capacity,
                                                      int32_t* out_count);
/** Size def from frame_count frames (1..65536; a few seconds of tracking, any poses)
 *  of the layout's joints each, frame after frame. The palm's joints both layouts have
 *  (wrist, thumb CMC, MCP joints) keep their distances whatever the pose: the palm's
 *  length and hand_breadth are the anthropometric ones (frusta_hand_def_set_size's
 *  proportions) that fit those distances best; hand_length is the middle MCP joint's
 *  distance along the palm plus the middle finger's bones (wrist to the straight
 *  fingertip). The def is refilled from them, its first joints placed along the hand at
 *  the palm's measured length, then each segment length is measured (over the frames:
 *  the mean of the middle half, less the noise's bias). A joint counts when its flags
 *  have FRUSTA_JOINT_POSITION_VALID and FRUSTA_JOINT_POSITION_TRACKED. Side and joint
 *  limits are kept; a segment no frame measures keeps its proportional length. Refused
 *  (def unchanged, the message naming the joints) when the frames never have the middle
 *  finger's joints, or pairs of palm joints that give both its length and breadth.
 *  Thread: any. */
FRUSTA_API frusta_result frusta_calibrate_hand_def(const frusta_tracked_joint* frames,
                                                   int32_t frame_count, int32_t layout,
                                                   frusta_hand_def* def);

/* ---------------------------------------------------------------- geometry queries */

/** Which part of a segment solid is nearest to a sphere. */
typedef enum frusta_feature {
  FRUSTA_FEATURE_SIDE = 0,     /* the frustum's lateral surface (or an end cap face) */
  FRUSTA_FEATURE_DISTAL = 1,   /* the ball at E (the fingertip on a finger's last segment) */
  FRUSTA_FEATURE_PROXIMAL = 2  /* the ball at D (a joint ball) */
} frusta_feature;

/** Everything one sphere/segment query knows. */
typedef struct frusta_contact_query {
  int32_t struct_size;         /* sizeof(frusta_contact_query); set it before the call */
  int32_t feature;             /* frusta_feature nearest the sphere (exact reference) */
  int32_t patent_contact;      /* 1 if seed eq. 5 reports contact (for comparison only) */
  int32_t contact;             /* 1 if the engine's conservative test reports contact */
  double distance;             /* metres, exact signed gap between the sphere and the
                                  segment solid; negative = penetration depth (a lower
                                  bound on depth inside the union of parts) */
  double hand_point[3];        /* metres, nearest point on the segment solid's surface */
  double object_point[3];      /* metres, the sphere's surface point nearest the hand */
  double normal[3];            /* unit, from the sphere's centre towards the hand */
  double axial;                /* k of seed eq. 4: 0 at E, 1 at D (0 if the length is 0) */
} frusta_contact_query;

/** Constraint forms; both have the same zero set (touching). */
typedef enum frusta_constraint_form {
  FRUSTA_CONSTRAINT_SQUARED = 0,  /* seed eq. 9 / eq. 10, metres squared */
  FRUSTA_CONSTRAINT_DISTANCE = 1  /* signed gap along the surface normal, metres */
} frusta_constraint_form;

/** A constraint value g >= 0 (non-penetrating) with its analytic gradient. */
typedef struct frusta_constraint {
  int32_t struct_size;    /* sizeof(frusta_constraint); set it before the call */
  int32_t feature;        /* frusta_feature whose constraint this is */
  double value;           /* metres or metres squared, by form */
  double grad_proximal[3];/* dg/dD */
  double grad_distal[3];  /* dg/dE */
  double grad_center[3];  /* dg/dO, the sphere's centre */
} frusta_constraint;

/** Query one sphere against one segment solid. Radii must be >= 0 and every value
 *  finite with magnitude <= 1e6 m. out->struct_size must be set. Thread: any. */
FRUSTA_API frusta_result frusta_query_contact(const frusta_segment* segment,
                                              const frusta_sphere* sphere,
                                              frusta_contact_query* out);
/** The constraint of the feature the endpoint rule (seed eqs. 10-11) picks (side,
 *  distal ball or proximal ball), or of an end ball where that ball bulges past the
 *  picked feature, so value < 0 exactly when the sphere overlaps the solid. In the
 *  given form, with its gradient with respect to D, E and the sphere's centre. Same
 *  input rules as frusta_query_contact. Thread: any. */
FRUSTA_API frusta_result frusta_constraint_eval(const frusta_segment* segment,
                                                const frusta_sphere* sphere, int32_t form,
                                                frusta_constraint* out);

/* ---------------------------------------------------------------- sphere trees */

/** Sphere-tree handle (an object's shape). Opaque; pass by value; zero means null. */
typedef struct frusta_tree_id {
  int32_t index1;      /* slot + 1; 0 is null */
  uint16_t world0;     /* always 0: trees are standalone */
  uint16_t generation; /* bumped when the slot is reused */
} frusta_tree_id;

/** Bake parameters. Leaves are spheres fitted to the surface from inside plus
 *  inscribed spheres filling the interior; see README "Sphere trees and baking".
 *  Every field has a range, checked by frusta_create_sphere_tree_from_mesh before
 *  anything is baked (FRUSTA_ERROR_OUT_OF_RANGE, or FRUSTA_ERROR_NOT_FINITE for
 *  NaN/infinity, naming the field); frusta-bake's options have the same ranges. */
typedef struct frusta_bake_def {
  int32_t struct_size;   /* sizeof(frusta_bake_def) */
  int32_t branching;     /* children per node, 2..16; default 4 */
  double target_error;   /* metres, bound on both error figures, 1e-5..1 (10 um: what
                            float geometry resolves on a hand-sized object; 1 m: spheres
                            larger than any hand); default 0.001 */
  int64_t max_leaves;    /* leaf budget, 1..2^24; a target it does not fit is coarsened
                            until the cover fits (the tree's error figures say how
                            far); default 200000 */
  int32_t max_depth;     /* 1..40; a deeper tree is refused; default 40 */
  int32_t reserved0;     /* explicit padding */
  int64_t error_samples; /* points behind each error figure, 1e3..1e7 (each point is kept
                            in memory while measuring); default 100000 */
  uint64_t seed;         /* sampling seed, any value: same mesh and seed, same tree;
                            default 1 */
  int32_t internal_value;/* set by frusta_default_bake_def(); do not touch */
  int32_t reserved1;     /* explicit padding */
} frusta_bake_def;

/** What a tree holds and how well it fits the mesh it was baked from. */
typedef struct frusta_sphere_tree_info {
  int32_t struct_size;       /* sizeof(frusta_sphere_tree_info); set it before the call */
  int32_t branching;         /* children per node */
  int32_t depth;             /* levels below the root */
  int32_t leaf_count;        /* leaf spheres */
  int32_t node_count;        /* all nodes, leaves included */
  int32_t triangle_count;    /* of the baked mesh */
  double bounds_min[3];      /* metres, of the leaves, object frame */
  double bounds_max[3];      /* metres, the upper corner */
  double target_error;       /* metres, as baked */
  double uncovered_error;    /* metres: largest distance from the surface to the leaves */
  double protruding_error;   /* metres: largest height of the leaves above the surface */
  double bake_seconds;       /* how long the bake took */
  int64_t error_samples;     /* points behind each figure */
  int32_t target_met;        /* 1 if both figures are within target_error */
  int32_t reserved0;         /* explicit padding */
} frusta_sphere_tree_info;

/** One node a tree query found: a leaf (leaf >= 0), or with max_level an inner node
 *  standing in for its subtree (leaf = -1). */
typedef struct frusta_tree_hit {
  int32_t node;          /* the node's index in the tree */
  int32_t leaf;          /* the leaf's stable number, or -1 for an inner node */
  frusta_sphere sphere;  /* world frame (through the pose given to the query) */
} frusta_tree_hit;

/** Defaults for frusta_create_sphere_tree_from_mesh. Thread: any. */
FRUSTA_API frusta_bake_def frusta_default_bake_def(void);

/** Create a sphere tree by baking it from triangles: vertices are vertex_count xyz
 *  triples in metres (right-handed object frame), indices are index_count / 3
 *  triangles wound counter-clockwise seen from outside. Blocks for the bake's duration
 *  (seconds for 10^5 triangles): call it off any frame loop. A target that does not
 *  fit in max_leaves is coarsened until the whole object is covered within them, and
 *  the tree is still returned; check info.target_met and its error figures.
 *  The baking is done by the baker library (libfrusta_bake.so; Embree), loaded from
 *  beside this library on first use (or from the path in FRUSTA_BAKE_PLUGIN); where
 *  it is not installed (platforms without Embree) this fails with
 *  FRUSTA_ERROR_UNAVAILABLE, and trees come from frusta-bake's .frtree files.
 *  Thread: any; bakes on different threads run concurrently. */
FRUSTA_API frusta_result frusta_create_sphere_tree_from_mesh(const float* vertices,
                                                             int32_t vertex_count,
                                                             const int32_t* indices,
                                                             int32_t index_count,
                                                             const frusta_bake_def* def,
                                                             frusta_tree_id* out_tree);
/** Create a sphere tree from a .frtree file (UTF-8 path). Truncated, corrupt or
 *  other-version files are refused with FRUSTA_ERROR_FILE_FORMAT or
 *  FRUSTA_ERROR_CORRUPT_FILE naming the problem. Thread: any. */
FRUSTA_API frusta_result frusta_create_sphere_tree_from_file(const char* path,
                                                             frusta_tree_id* out_tree);
/** Create a sphere tree from the bytes of a .frtree file in memory (size bytes at data,
 *  0..the largest valid tree: an engine's asset, with no temporary file), checked as
 *  frusta_create_sphere_tree_from_file checks a file. The bytes may go once this
 *  returns. Thread: any. */
FRUSTA_API frusta_result frusta_create_sphere_tree_from_memory(const void* data, int64_t size,
                                                               frusta_tree_id* out_tree);

/** Bake-job handle: a bake running on a thread of its own. Opaque; pass by value; zero
 *  means null. */
typedef struct frusta_bake_job_id {
  int32_t index1;      /* slot + 1; 0 is null */
  uint16_t world0;     /* always 0: jobs are standalone */
  uint16_t generation; /* bumped when the slot is reused */
} frusta_bake_job_id;

/** Start baking a tree as frusta_create_sphere_tree_from_mesh does, on a thread of the
 *  job's own, so that an editor can show its progress and cancel it. The def is checked
 *  now (its errors come from here); the mesh is copied, so its arrays may go at once,
 *  and checked by the bake (its errors come from frusta_finish_bake_job). Every started
 *  job must be finished with frusta_finish_bake_job, which frees it. Thread: any. */
FRUSTA_API frusta_result frusta_start_bake(const float* vertices, int32_t vertex_count,
                                           const int32_t* indices, int32_t index_count,
                                           const frusta_bake_def* def,
                                           frusta_bake_job_id* out_job);
/** How far a job has come: *out_fraction in 0..1, never decreasing, and *out_done 1
 *  once it has ended (baked, failed or cancelled; finishing it then does not wait).
 *  Thread: any. */
FRUSTA_API frusta_result frusta_bake_job_progress(frusta_bake_job_id job, double* out_fraction,
                                                  int32_t* out_done);
/** Ask a job to stop: it ends soon after (within a few thousand of the baker's queries)
 *  and finishing it gives FRUSTA_ERROR_CANCELLED, even if it had ended already (its
 *  tree is dropped). Thread: any. */
FRUSTA_API frusta_result frusta_cancel_bake_job(frusta_bake_job_id job);
/** Wait for a job to end, free it (its id turns stale) and give what it made: its tree
 *  in *out_tree, or the bake's error (as frusta_create_sphere_tree_from_mesh reports
 *  it), or FRUSTA_ERROR_CANCELLED. out_tree may not be null: a job is freed either way.
 *  Thread: any; one thread per job. */
FRUSTA_API frusta_result frusta_finish_bake_job(frusta_bake_job_id job, frusta_tree_id* out_tree);
/** Destroy a tree; its id becomes stale. Worlds whose objects use it keep it alive.
 *  Thread: any, but not while another thread uses the same tree. */
FRUSTA_API frusta_result frusta_destroy_sphere_tree(frusta_tree_id tree);
/** Write a tree to path (UTF-8) atomically (a reader never sees half a file).
 *  Thread: any. */
FRUSTA_API frusta_result frusta_sphere_tree_save(frusta_tree_id tree, const char* path);
/** 1 if the id names a live tree, else 0. Thread: any. */
FRUSTA_API int32_t frusta_sphere_tree_is_valid(frusta_tree_id tree);
/** Fill info (set info->struct_size first). Thread: any. */
FRUSTA_API frusta_result frusta_sphere_tree_get_info(frusta_tree_id tree,
                                                     frusta_sphere_tree_info* info);
/** Copy the leaf spheres, metres, object frame, in their stable numbering, by the
 *  output-array rule (capacity 0 and out null ask for the count). Thread: any. */
FRUSTA_API frusta_result frusta_sphere_tree_get_leaves(frusta_tree_id tree, frusta_sphere* out,
                                                       int32_t capacity, int32_t* out_count);
/** Every leaf (or, with max_level >= 0, every node at that level) within margin
 *  metres of a world segment, for the object placed at pose (null: identity), copied
 *  by the output-array rule: *out_count is the number found, which may exceed
 *  capacity. Thread: any. */
FRUSTA_API frusta_result frusta_sphere_tree_query_segment(frusta_tree_id tree,
                                                          const frusta_pose* pose,
                                                          const frusta_segment* segment,
                                                          double margin, int32_t max_level,
                                                          frusta_tree_hit* out, int32_t capacity,
                                                          int32_t* out_count);

/* ---------------------------------------------------------------- world */

/* A world holds hands and objects and steps them: each step turns every hand's
 * haptic input (the glove) into a graphic hand that never sinks into an object,
 * the contact forces (seed eqs. 12-13), what each device receives and what each
 * object receives. It runs on its own thread at rate_hz (frusta_world_start) or is
 * stepped by the host (frusta_world_step). Host and stepping thread never wait for
 * each other: object commands are queued and applied at the next step; outputs are
 * published as a snapshot the host latches with frusta_world_read. The threads
 * named below (host, input, any) are the Conventions' at the top: the host is the
 * thread that created the world. */

/** World handle. Opaque; pass by value; zero means null. */
typedef struct frusta_world_id {
  int32_t index1;      /* slot + 1; 0 is null */
  uint16_t world0;     /* always 0 */
  uint16_t generation; /* bumped when the slot is reused */
} frusta_world_id;

/** Object handle within a world. Opaque; pass by value; zero means null. */
typedef struct frusta_object_id {
  int32_t index1;      /* object slot + 1; 0 is null */
  uint16_t world0;     /* the owning world: slot + 1, and its generation's low byte */
  uint16_t generation; /* bumped when the slot is reused */
} frusta_object_id;

/** World creation parameters; from frusta_default_world_def(). */
typedef struct frusta_world_def {
  int32_t struct_size;          /* sizeof(frusta_world_def) */
  int32_t max_objects;          /* object slots, 1..65535; default 64 */
  double rate_hz;               /* own thread's rate, and dynamic objects' time step
                                   1/rate_hz; 1..100000; default 1000 */
  double spin_us;               /* the own thread spins this long before each tick
                                   instead of sleeping, for an on-time wake; 0..one
                                   period; default 200 */
  double gravity[3];            /* m/s^2 on dynamic objects; default 0 (off) */
  double prediction_margin;     /* Delta_r, metres: detection margin and the most any
                                   hand point moves per sub-step; 1e-5..0.1 and below
                                   the smallest finger radius; default 0.002 */
  double lod_error;             /* metres, the level-of-detail error budget: a tree
                                   node whose sphere stands out of its leaves by no
                                   more than this stands in for them, so a hand may
                                   stop up to this far short of the leaves (0: the
                                   leaves); 0..1; default 0 */
  int32_t max_iterations;       /* re-linearisations per solver stage, 1..100; default 2 */
  int32_t max_substeps;         /* per step, 1..1024; default 64 */
  int32_t max_contacts_per_hand;/* kept per hand per step, 0..65536; default 256 */
  int32_t command_capacity;     /* queued object and hand commands between steps,
                                   1..2^20 (rounded up to a power of two); default 256 */
  int32_t max_hands;            /* hand slots, 1..64; default 8. An empty slot costs a
                                   few kilobytes and no step time */
  int32_t realtime_priority;    /* 1: the own thread and the threads of gloves driving
                                   its hands ask the system for real-time priority
                                   (Linux SCHED_FIFO: root or an rtprio limit; Windows
                                   THREAD_PRIORITY_TIME_CRITICAL), and run at normal
                                   priority where it is refused (frusta_world_state
                                   says which); 0: normal priority. Default 1 */
  /* device limits: every output is scaled down to fit, never turned */
  double max_fingertip_force;   /* newtons, per finger; default 10 */
  double max_finger_resistance; /* newtons, per finger; default 10 */
  double max_joint_torque;      /* newton-metres, per joint; default 0.5 */
  double max_palm_force;        /* newtons; default 20 */
  double max_palm_torque;       /* newton-metres; default 1 */
  /* timed input (frusta_world_set_haptic_at): each step plays a hand's samples this
     far behind its time */
  double input_delay;           /* seconds, 0..0.1; default 0.01: the p99 of a host's
                                   delivery lateness on a busy machine. A host that
                                   delivers later than this moves the hand on
                                   extrapolated samples until its own come */
  double max_extrapolation;     /* seconds, 0..0.1: how long past its newest sample a
                                   hand moves on at the sample's velocity before it
                                   holds; default 0.04 */
  int32_t max_candidates_per_hand; /* object spheres near a hand that its buffers hold,
                                   made when the hand is added (about 400 bytes each),
                                   1..262144; default 1024 (the grasp of a ball
                                   of 10^4 leaves meets up to 951, of 10^5 leaves
                                   8,760). A hand that meets more grows them once on
                                   the stepping thread: an allocation in a real-time
                                   step */
  int32_t internal_value;       /* set by frusta_default_world_def(); do not touch */
} frusta_world_def;

/** An object as it is added: where, what it is made of, and whether the world moves
 *  it. Kinematic objects (dynamic = 0) stay where the host puts them; a host with its
 *  own rigid-body engine keeps them kinematic and applies each object's reaction
 *  wrench itself. Dynamic objects the world integrates at its rate under the hands'
 *  reactions and gravity. From frusta_default_object_def(). */
typedef struct frusta_object_def {
  int32_t struct_size;          /* sizeof(frusta_object_def) */
  int32_t dynamic;              /* 1: dynamic; 0: kinematic (default) */
  frusta_pose pose;             /* the object frame (its origin is the centre of mass) */
  double stiffness[3];          /* G of seed eq. 12, diagonal in the object frame, N/m,
                                   0..1e9; default 400 */
  double friction;              /* mu of seed eq. 13, 0..100; default 0.6 */
  double tangential_stiffness;  /* the stick spring, N/m, 0..1e9; default 1e4 */
  double normal_damping;        /* on how fast a contact sinks in, N s/m, 0..1e9;
                                   default 0 (eq. 12 exactly); 2 sqrt(k m) settles a
                                   held object of mass m */
  double tangential_damping;    /* on how fast a sticking contact slides, N s/m, 0..1e9;
                                   default 0; 2 sqrt(tangential_stiffness m) keeps a
                                   held object of mass m from being kicked by the
                                   hand's jitter */
  double mass;                  /* kg, 1e-6..1e4; default 0.1 */
  double inertia[3];            /* principal moments in the object frame, kg m^2,
                                   1e-13..1e4, each at most the sum of the other two
                                   (a real body's); default 4e-5 */
  double linear_velocity[3];    /* m/s, world; |each| <= 100; default 0 */
  double angular_velocity[3];   /* rad/s, world; |each| <= 1000; default 0 */
  double linear_damping;        /* 1/s, 0..1000; default 0 */
  double angular_damping;       /* 1/s, 0..1000; default 0 */
  int32_t internal_value;       /* set by frusta_default_object_def(); do not touch */
  int32_t reserved0;            /* explicit padding */
} frusta_object_def;

/** What frusta_world_read latches: the newest step's summary. */
typedef struct frusta_world_state {
  int32_t struct_size;          /* sizeof(frusta_world_state); set it before the call */
  int32_t hand_count;           /* hands present at the step */
  uint64_t step;                /* steps so far; 0 before the first */
  double time;                  /* seconds: steps times 1/rate_hz */
  double step_us;               /* this step's time, microseconds */
  double step_us_p50, step_us_p99, step_us_max; /* over every step so far */
  double wake_late_us_p50, wake_late_us_p99, wake_late_us_max; /* own thread's jitter */
  double achieved_rate_hz;      /* own thread: steps per second since start; 0 if none */
  int64_t overruns;             /* ticks the own thread lost to late steps */
  int64_t rejected_inputs;      /* haptic inputs the solver could not place: a hand
                                   that starts inside objects with no free placement
                                   near (bad input is refused by set_haptic instead) */
  int32_t object_count;         /* objects present at the step */
  int32_t realtime;             /* 1: the own thread runs at real-time priority */
} frusta_world_state;

/** One hand as the latched step left it. World frame. */
typedef struct frusta_world_hand {
  int32_t struct_size;          /* sizeof(frusta_world_hand); set it before the call */
  int32_t solved;               /* 1: the hand has had a valid input (0 until then) */
  frusta_pose graphic_palm;     /* the displayed hand: palm pose */
  double graphic_angles[FRUSTA_HAND_JOINT_COUNT]; /* and joint angles, radians */
  frusta_pose haptic_palm;      /* the input the step used */
  double haptic_angles[FRUSTA_HAND_JOINT_COUNT]; /* and its joint angles, radians */
  int32_t contact_count;        /* all contacts, even beyond max_contacts_per_hand */
  int32_t pressing;             /* contacts whose haptic point lies inside */
  int32_t slipping;             /* pressing contacts sliding (friction at mu |F|) */
  int32_t substeps;             /* solver sub-steps this step */
  int32_t lagging;              /* 1: the step budget (max_substeps, or the own
                                   thread's share of the period) stopped the hand short:
                                   each contact patch's push then changes at most its
                                   stiffness times its move plus 0.02 N a step, until it
                                   is its own again */
  int32_t infeasible;           /* 1: a contact QP had no point meeting every row it
                                   was given (nearly parallel or contradictory
                                   constraints); the hand stayed at its last safe
                                   estimate, short of its input */
  int32_t ignored_objects;      /* objects put inside the hand that it passes through
                                   until they part (see frusta_create_object) */
  int32_t input_late;           /* 1: the step played a time past the hand's newest
                                   sample (its driver is late or stopped): the input
                                   was extrapolated (at most max_extrapolation), then
                                   held */
  /* device outputs, each clamped to the world's limits; pick what the device renders */
  double fingertip_force[FRUSTA_FINGER_COUNT][3]; /* on each distal segment, newtons */
  double finger_resistance[FRUSTA_FINGER_COUNT];  /* |force| on each finger, newtons */
  double joint_torque[FRUSTA_HAND_JOINT_COUNT];   /* J^T F per joint, newton-metres */
  double palm_force[3];         /* newtons */
  double palm_torque[3];        /* newton-metres, about the haptic palm origin */
} frusta_world_hand;

/** One contact of a hand and the force on the hand there. World frame. */
typedef struct frusta_world_contact {
  frusta_object_id object;      /* the object touched */
  int32_t body;                 /* finger * 3 + segment, or 15 for the palm */
  int32_t leaf;                 /* the object's leaf, or -1 for an inner node */
  int32_t slipping;             /* 1: friction at mu |F| */
  int32_t reserved0;            /* explicit padding */
  double distance;              /* metres, exact gap (>= -tolerance) */
  double graphic_point[3];      /* P_ig, metres */
  double haptic_point[3];       /* P_ih: the same material point on the haptic hand */
  double normal[3];             /* unit, from the object towards the hand */
  double normal_force[3];       /* on the hand, newtons */
  double friction[3];           /* on the hand, newtons */
} frusta_world_contact;

/** One object as the latched step left it. */
typedef struct frusta_object_state {
  int32_t struct_size;          /* sizeof(frusta_object_state); set it before the call */
  int32_t dynamic;              /* 1: the world moves it (see frusta_object_def) */
  frusta_pose pose;             /* where the hands met it this step */
  double linear_velocity[3];    /* m/s */
  double angular_velocity[3];   /* rad/s */
  double reaction_force[3];     /* from every hand, newtons: what a host engine applies;
                                   while held, what carrying it takes */
  double reaction_torque[3];    /* about the pose position, newton-metres */
  int32_t ignoring_hands;       /* hands the object was put inside, which pass through
                                   it until they part (frusta_world_get_object_ignored_by
                                   names them) */
  int32_t held;                 /* 1: a dynamic object a hand's grasp holds: two of its
                                   pads oppose and their friction bears its weight, so
                                   it moves with that hand's palm until the squeeze
                                   opens (the glove still feels every push) */
} frusta_object_state;

/** Defaults for frusta_create_world. Thread: any. */
FRUSTA_API frusta_world_def frusta_default_world_def(void);
/** Defaults for frusta_create_object. Thread: any. */
FRUSTA_API frusta_object_def frusta_default_object_def(void);

/** Create a world (no thread yet; see frusta_world_start). Thread: any; the calling
 *  thread is the world's host. */
FRUSTA_API frusta_result frusta_create_world(const frusta_world_def* def, frusta_world_id* out_world);
/** Stop the world's thread if running, close its gloves, then destroy it with its
 *  hands and objects (the trees they used stay the caller's). Its id and every id
 *  naming it (hands, objects, gloves) turn stale. No other thread may be calling into
 *  the world meanwhile. Thread: host. */
FRUSTA_API frusta_result frusta_destroy_world(frusta_world_id world);
/** 1 if the id names a live world, else 0. Thread: any. */
FRUSTA_API int32_t frusta_world_is_valid(frusta_world_id world);

/** Create a hand in the world, built from def, at any time (the world's own thread may
 *  be running); *out_hand names it in every call on the world's hands
 *  (frusta_world_set_haptic, frusta_world_get_hand, ..., frusta_device_def.hand).
 *  Queued like an object: it takes haptic inputs at once and is solved from the next
 *  step on; the frusta_world_get_* calls refuse it (FRUSTA_ERROR_STALE_ID) until
 *  frusta_world_read has latched such a step. All the memory it needs is allocated
 *  here, on the host thread. Its first input is placed outside every object (or, with
 *  no free placement near, counted in rejected_inputs). The world's solver settings
 *  are checked against the hand here. FRUSTA_ERROR_CAPACITY when max_hands hands are
 *  present or still being let go of (see frusta_destroy_world_hand), or the command
 *  queue is full (step the world). Thread: host. */
FRUSTA_API frusta_result frusta_create_world_hand(frusta_world_id world,
                                                  const frusta_hand_def* def,
                                                  frusta_hand_id* out_hand);
/** Destroy a hand of a world (queued; the id names its world). Its id turns stale at
 *  once for the calls that change the world: frusta_world_set_haptic from an input
 *  thread still feeding it gets FRUSTA_ERROR_STALE_ID. The frusta_world_get_* calls
 *  report the latched step, in which the hand is present until a step has applied the
 *  removal. A hand a glove drives is refused (FRUSTA_ERROR_WRONG_STATE) until
 *  frusta_destroy_device closes the glove. The hand's memory is freed on the host
 *  thread, never in a step, by the first frusta_world_read that latches a step which
 *  applied the removal; its slot takes a new hand from then on. Thread: host (of the
 *  hand's world). */
FRUSTA_API frusta_result frusta_destroy_world_hand(frusta_hand_id hand);
/** Set a world hand's haptic input (the glove): palm pose (metres, world frame) and
 *  FRUSTA_HAND_JOINT_COUNT joint angles (radians, finger-major), stamped with now.
 *  A world the host steps takes the newest as it is at the next step; a world on its
 *  own thread plays it input_delay late, as frusta_world_set_haptic_at does, but
 *  never extrapolates past it (when it was set is not when it was measured; a host
 *  that can, stamps its samples with their own times). The one rule for every input of a hand (this call,
 *  frusta_hand_set_joint_angles, a glove's samples): positions within 1e6 m,
 *  quaternion norm in [0.5, 2] (normalised), |angle| <= FRUSTA_MAX_JOINT_ANGLE
 *  (clamped into the hand's limits). What this call accepts the next step uses; what
 *  breaks the rule is refused here. Lock-free and allocation-free.
 *  FRUSTA_ERROR_WRONG_STATE on a hand a glove drives (frusta_create_device);
 *  FRUSTA_ERROR_STALE_ID from the moment the host destroys the hand, even while this
 *  call runs on another thread. Thread: input. */
FRUSTA_API frusta_result frusta_world_set_haptic(frusta_world_id world, frusta_hand_id hand,
                                                 const frusta_pose* palm, const double* angles,
                                                 int32_t count);
/** frusta_world_set_haptic for a sample stamped with its time: `time` in seconds on the
 *  world's clock, which is frusta_now()'s while the world runs on its own thread
 *  (frusta_world_start), and the world's step time while the host steps it (the step
 *  after n steps is at (n + 1) / rate_hz: frusta_world_state.time is the latched
 *  step's). A host with its own clock stamps each sample with that clock plus an
 *  offset to the world's. Each step plays the hand's samples input_delay behind its
 *  own time: between two samples, interpolated (palm straight, its rotation along the
 *  shorter arc, angles straight); before the first, the first; past the newest,
 *  extrapolated from its velocity for at most max_extrapolation, then held
 *  (frusta_world_hand.input_late). A host that stalls and then delivers its samples
 *  in a burst so moves the hand as the samples say. time must be finite, 0..1e9 s,
 *  and later than the hand's previous timed sample (FRUSTA_ERROR_OUT_OF_RANGE);
 *  otherwise as frusta_world_set_haptic (the two are not meant to be mixed on one
 *  hand). Lock-free and allocation-free. Thread: input. */
FRUSTA_API frusta_result frusta_world_set_haptic_at(frusta_world_id world, frusta_hand_id hand,
                                                    double time, const frusta_pose* palm,
                                                    const double* angles, int32_t count);
/** Seconds on Frusta's monotonic clock (the steady clock a world on its own thread
 *  steps by, and so the clock of frusta_world_set_haptic_at's time for such a world).
 *  Thread: any. */
FRUSTA_API double frusta_now(void);

/** Create an object in the world with the tree's shape; queued, present from the next
 *  step. The world keeps the tree alive while it uses it, even if the tree's id is
 *  destroyed. An object created where a graphic hand already is, overlapping it, is
 *  ignored by that hand until they part: the hand passes through it, touches it
 *  nowhere and pushes it with no force, rather than being trapped in it or flung out
 *  of it (frusta_object_state.ignoring_hands, frusta_world_get_object_ignored_by and
 *  frusta_world_hand.ignored_objects show it; move the hand out, or the object away,
 *  to make it solid to the hand). FRUSTA_ERROR_CAPACITY when max_objects are present
 *  or the command queue is full (step the world). Thread: host. */
FRUSTA_API frusta_result frusta_create_object(frusta_world_id world, frusta_tree_id tree,
                                              const frusta_object_def* def,
                                              frusta_object_id* out_object);
/** Destroy an object of a world (queued; the id names its world). Its id is refused at
 *  once by the calls that change the world; frusta_world_get_object reports the
 *  latched step, in which the object is present until a step has applied the removal.
 *  Thread: host (of the object's world). */
FRUSTA_API frusta_result frusta_destroy_object(frusta_object_id object);
/** Put an object at a pose (metres, world frame), at rest (queued). A hand it is put
 *  into ignores it until they part, as for frusta_create_object; an object the
 *  world's dynamics move into a hand is pushed by it as usual. Thread: host. */
FRUSTA_API frusta_result frusta_world_set_object_pose(frusta_world_id world,
                                                      frusta_object_id object,
                                                      const frusta_pose* pose);
/** Hand an object to the world's dynamics (1) or take it back, at rest (0); queued.
 *  Thread: host. */
FRUSTA_API frusta_result frusta_world_set_object_dynamic(frusta_world_id world,
                                                         frusta_object_id object, int32_t dynamic);

/** One step at 1/rate_hz: apply queued commands, solve every hand, publish. Not
 *  while the world's own thread runs (FRUSTA_ERROR_WRONG_STATE). Thread: host. */
FRUSTA_API frusta_result frusta_world_step(frusta_world_id world);
/** Run the world on its own thread at def.rate_hz on absolute deadlines (sleep, then
 *  spin def.spin_us) until frusta_world_stop. FRUSTA_ERROR_WRONG_STATE if running.
 *  Thread: host. */
FRUSTA_API frusta_result frusta_world_start(frusta_world_id world);
/** Stop the world's thread (returns once its current step is done); no effect if
 *  none runs. Thread: host. */
FRUSTA_API frusta_result frusta_world_stop(frusta_world_id world);

/** Latch the newest published step (lock-free; never a torn one) and fill state (set
 *  state->struct_size first). The frusta_world_get_* functions below read the latched
 *  step until the next call. Thread: host. */
FRUSTA_API frusta_result frusta_world_read(frusta_world_id world, frusta_world_state* state);
/** One hand of the latched step (set out->struct_size first). FRUSTA_ERROR_STALE_ID
 *  for a hand destroyed, or created after the latched step. Thread: host. */
FRUSTA_API frusta_result frusta_world_get_hand(frusta_world_id world, frusta_hand_id hand,
                                               frusta_world_hand* out);
/** The contacts of one hand in the latched step (at most max_contacts_per_hand), by
 *  the output-array rule (capacity 0 and out null ask for the count); refused as
 *  frusta_world_get_hand. Thread: host. */
FRUSTA_API frusta_result frusta_world_get_contacts(frusta_world_id world, frusta_hand_id hand,
                                                   frusta_world_contact* out, int32_t capacity,
                                                   int32_t* out_count);
/** One object of the latched step (set out->struct_size first).
 *  FRUSTA_ERROR_STALE_ID for an object destroyed, or created after the latched step.
 *  Thread: host. */
FRUSTA_API frusta_result frusta_world_get_object(frusta_world_id world, frusta_object_id object,
                                                 frusta_object_state* out);
/** *out_ignored = 1 if, in the latched step, the hand ignores the object (it was
 *  created or moved into the hand and they have not parted since; see
 *  frusta_create_object), else 0. Both must be in the latched step
 *  (FRUSTA_ERROR_STALE_ID otherwise). Thread: host. */
FRUSTA_API frusta_result frusta_world_get_object_ignored_by(frusta_world_id world,
                                                            frusta_object_id object,
                                                            frusta_hand_id hand,
                                                            int32_t* out_ignored);

/** Which of a world hand's two hands a geometry call copies. */
typedef enum frusta_hand_kind {
  FRUSTA_HAND_KIND_GRAPHIC = 0, /* the displayed hand, outside every object */
  FRUSTA_HAND_KIND_HAPTIC = 1   /* the input as the solver aims at it, angles clamped to
                                   the limits: the glove's "ghost" hand, inside objects
                                   where the user pushes */
} frusta_hand_kind;

/** The world geometry of one hand of the latched step (which: frusta_hand_kind), as
 *  frusta_hand_get_segments gives a standalone hand's: FRUSTA_HAND_SEGMENT_COUNT
 *  segments, finger-major (thumb first), proximal to distal, metres, by the
 *  output-array rule; the last segment of each finger has its tip hemisphere at the
 *  distal end. Worked out from the latched hand's pose and joint angles, exactly as a
 *  standalone hand given them. FRUSTA_ERROR_WRONG_STATE while the hand has had no
 *  input (frusta_world_hand.solved 0). Thread: host. */
FRUSTA_API frusta_result frusta_world_get_hand_segments(frusta_world_id world,
                                                        frusta_hand_id hand, int32_t which,
                                                        frusta_segment* out, int32_t capacity,
                                                        int32_t* out_count);
/** The palm spheres of one hand of the latched step in world coordinates, as
 *  frusta_hand_get_palm_spheres gives a standalone hand's, by the output-array rule
 *  (capacity 0 and out null ask for the count); otherwise as
 *  frusta_world_get_hand_segments. Thread: host. */
FRUSTA_API frusta_result frusta_world_get_hand_palm_spheres(frusta_world_id world,
                                                            frusta_hand_id hand, int32_t which,
                                                            frusta_sphere* out, int32_t capacity,
                                                            int32_t* out_count);

/* ---------------------------------------------------------------- devices
 * A force-feedback glove drives one hand of a world. It is opened by URI:
 *   opengloves:PATH?baud=N       OpenGloves alpha encoding over serial (LucidGloves
 *                                and its kin; USB serial or Bluetooth RFCOMM)
 *   serial:PATH?baud=N           Frusta's binary profile over serial
 *   hid:VID:PID[:SERIAL]         Frusta's binary profile over HID reports (hex ids)
 *   replay:FILE?speed=1|max&loop=0|1   a recording, in real time or as fast as read
 * and any of them takes &record=FILE to record its input stream for replay. baud is
 * 115200 unless given. A recording (replayed or recorded) is a regular file of at most
 * 1 GiB; a FIFO, device or folder is refused, and so is recording over the file being
 * replayed. Each open glove has a thread of its own (none without one):
 * it feeds the glove's samples to the hand as frusta_world_set_haptic would, and
 * sends the glove its command at the output rate. Safety: the command is the world's
 * device outputs cut to the glove's limits and rise rates, and drops to zero at once
 * when no valid sample came for watchdog_s, the world has not stepped for
 * engine_timeout_s, the host has not called frusta_world_read for host_timeout_s, or
 * the glove disconnects; the glove is reopened every reconnect_interval_s and gets
 * zeros until it speaks again. Protocols: native/src/devices/binary_profile.md and
 * alpha_encoding.h. */

/** Device handle. Opaque; pass by value; zero means null. */
typedef struct frusta_device_id {
  int32_t index1;      /* the hand slot it drives + 1; 0 is null */
  uint16_t world0;     /* the owning world: slot + 1, and its generation's low byte */
  uint16_t generation; /* bumped at each open on that hand */
} frusta_device_id;

/** What the glove's outputs are: bits of frusta_device_def.outputs and status. */
typedef enum frusta_device_output {
  FRUSTA_DEVICE_OUTPUT_FINGER_RESISTANCE = 1, /* a brake per finger */
  FRUSTA_DEVICE_OUTPUT_FINGERTIP_FORCE = 2,   /* a force vector per fingertip, palm frame */
  FRUSTA_DEVICE_OUTPUT_JOINT_TORQUE = 4       /* a torque per finger joint */
} frusta_device_output;

/** Whether a glove is connected (frusta_device_status.state). */
typedef enum frusta_device_state {
  FRUSTA_DEVICE_CONNECTED = 1,    /* open, and its stream is up */
  FRUSTA_DEVICE_DISCONNECTED = 2, /* retrying every reconnect_interval_s */
  FRUSTA_DEVICE_CLOSED = 3        /* closed (frusta_destroy_device, or its world destroyed) */
} frusta_device_state;

/** Why the glove's output is held at zero now (frusta_device_status.watchdog). */
typedef enum frusta_watchdog_reason {
  FRUSTA_WATCHDOG_NONE = 0,           /* not held: the glove renders the world's outputs */
  FRUSTA_WATCHDOG_INPUT_STALLED = 1,  /* no valid sample for watchdog_s (or none yet) */
  FRUSTA_WATCHDOG_DISCONNECTED = 2,   /* the glove is disconnected */
  FRUSTA_WATCHDOG_ENGINE_STALLED = 3, /* the world has not stepped for engine_timeout_s */
  FRUSTA_WATCHDOG_HOST_STALLED = 4    /* no frusta_world_read for host_timeout_s */
} frusta_watchdog_reason;

/** How a glove is opened; from frusta_default_device_def(). */
typedef struct frusta_device_def {
  int32_t struct_size;           /* sizeof(frusta_device_def) */
  frusta_hand_id hand;           /* the world's hand it drives (frusta_create_world_hand);
                                    default null: set it */
  int32_t reserved1;             /* explicit padding */
  double output_rate_hz;         /* commands per second, 0 or 1..100000; 0: the world's rate,
                                    never above what the glove takes (100 for OpenGloves);
                                    default 0 */
  double watchdog_s;             /* 0.001..10; default 0.05 */
  double engine_timeout_s;       /* 0.001..10; default 0.05 */
  double host_timeout_s;         /* 0 (not watched) or 0.001..60; default 0.25 */
  double reconnect_interval_s;   /* 0.001..60; default 0.2 */
  double max_force_rate;         /* newtons per second a resistance or fingertip force
                                    may rise (falls are immediate), 0..1e9; default 500 */
  double max_torque_rate;        /* newton-metres per second, 0..1e9; default 25 */
  double max_finger_resistance;  /* newtons, 0..1e9; the glove's own limit if lower;
                                    default 10 */
  double max_fingertip_force;    /* newtons, 0..1e9; default 10 */
  double max_joint_torque;       /* newton-metres, 0..1e9; default 0.5 */
  /* OpenGloves calibration: raw units (0..analog_max) to radians, newtons to brake
     units. Per finger (thumb first) and flexion joint (first, second, third). Raw
     readings lie in 0..analog_max, curl_open and curl_closed at least 1 apart; flexions
     within +-pi, splay_span 1..analog_max, abduction_range 0..pi/2: */
  double curl_open[FRUSTA_FINGER_COUNT][3];      /* raw reading, finger straight; default 0 */
  double curl_closed[FRUSTA_FINGER_COUNT][3];    /* raw reading in a fist; default 4095 */
  double flexion_open[FRUSTA_FINGER_COUNT][3];   /* radians at curl_open; default 0 */
  double flexion_closed[FRUSTA_FINGER_COUNT][3]; /* radians at curl_closed; default a fist */
  double splay_center[FRUSTA_FINGER_COUNT];      /* raw splay of a straight finger; 2048 */
  double splay_span[FRUSTA_FINGER_COUNT];        /* raw splay for abduction_range; 2047 */
  double abduction_range[FRUSTA_FINGER_COUNT];   /* radians; default 15 degrees */
  double brake_full_scale;       /* newtons that set a brake to brake_units, > 0 and
                                    <= 1e6; default 10 */
  double brake_units;            /* the glove's full brake, 1..65535; default 1000 */
  double analog_max;             /* the largest raw reading, 1..1e9; default 4095 */
  int32_t internal_value;        /* set by frusta_default_device_def; do not touch */
  int32_t reserved0;
} frusta_device_def;

/** A glove's state and counters (frusta_device_get_status). */
typedef struct frusta_device_status {
  int32_t struct_size;           /* sizeof(frusta_device_status); set it before the call */
  int32_t state;                 /* frusta_device_state */
  int32_t watchdog;              /* frusta_watchdog_reason */
  int32_t outputs;               /* frusta_device_output bits the glove renders */
  int32_t fingers;               /* the glove's fingers, thumb first */
  int32_t has_palm_pose;         /* 1: the glove reports the palm (a tracker) */
  int32_t protocol_version;      /* announced by the glove (0: none) */
  int32_t recording_failed;      /* 1: the disk refused the recording, or it reached 1 GiB;
                                    the glove runs on */
  int64_t frames_ok;             /* samples taken */
  int64_t frames_corrupt;        /* bad checksum or syntax: dropped */
  int64_t frames_truncated;      /* cut short: dropped */
  int64_t frames_out_of_range;   /* well formed, impossible values: dropped */
  int64_t samples_rejected;      /* decoded, but breaking the rule of set_haptic (NaN,
                                    |angle| > FRUSTA_MAX_JOINT_ANGLE, ...): dropped */
  int64_t commands_sent;         /* commands written to the glove */
  int64_t commands_dropped;      /* the glove did not drain its input in time */
  int64_t reconnects;            /* times the glove came back */
  int64_t disconnects;           /* times it went away */
  int64_t watchdog_trips;        /* times the output was forced to zero */
  double input_rate_hz;          /* samples per second, by the glove's own clock and
                                    sequence where it sends them (the binary profile), else
                                    by arrival */
  double output_rate_hz;         /* in use */
  double last_sample_age_s;      /* -1: none yet */
  double max_finger_resistance;  /* newtons: the limits in use */
  double max_fingertip_force;    /* newtons */
  double max_joint_torque;       /* newton-metres */
  double finger_resistance[FRUSTA_FINGER_COUNT];  /* newtons, the last command's */
  double fingertip_force[FRUSTA_FINGER_COUNT][3]; /* newtons, palm frame */
} frusta_device_status;

#ifndef FRUSTA_BASE_DEVICE_KIND
#define FRUSTA_BASE_DEVICE_KIND
/** What frusta_enumerate_devices found (frusta_device_info.kind). */
typedef enum frusta_device_kind {
  FRUSTA_DEVICE_KIND_SERIAL = 1, /* a serial port: open as opengloves: or serial: */
  FRUSTA_DEVICE_KIND_HID = 2,    /* a vendor-defined HID device: hid: */
  FRUSTA_DEVICE_KIND_USB = 3     /* any USB device (for its ids; not opened directly) */
} frusta_device_kind;
#endif /* FRUSTA_BASE_DEVICE_KIND */

/** One device frusta_enumerate_devices found. */
typedef struct frusta_device_info {
  int32_t kind;                  /* frusta_device_kind */
  int32_t vendor_id;             /* USB/HID ids; -1 when unknown */
  int32_t product_id;            /* -1 when unknown */
  uint8_t uri[256];              /* UTF-8, NUL-terminated: a URI to open (serial ports
                                    as serial:PATH; use opengloves:PATH for those) */
} frusta_device_info;

/** Defaults for frusta_create_device. Thread: any. */
FRUSTA_API frusta_device_def frusta_default_device_def(void);
/** List the serial ports, HID devices and USB devices present now, by the
 *  output-array rule (capacity 0 and out null ask for the count). Thread: any (it
 *  reads /dev, hidapi and the system's USB device list; slow: not for a frame loop). */
FRUSTA_API frusta_result frusta_enumerate_devices(frusta_device_info* out, int32_t capacity,
                                                  int32_t* out_count);
/** Open the glove at uri (UTF-8) to drive the world's hand def->hand, and start its
 *  thread. A glove absent at open is an error (FRUSTA_ERROR_IO, naming it), not a
 *  retry; one glove per hand (FRUSTA_ERROR_WRONG_STATE). While open,
 *  frusta_world_set_haptic on that hand is refused, and so is destroying the hand: its
 *  palm comes from frusta_device_set_palm_pose unless the glove reports one.
 *  Thread: host. */
FRUSTA_API frusta_result frusta_create_device(frusta_world_id world, const char* uri,
                                              const frusta_device_def* def,
                                              frusta_device_id* out_device);
/** Send the glove a zero command, stop its thread, close it (the id names its world).
 *  The id turns stale and the hand takes frusta_world_set_haptic again.
 *  frusta_destroy_world closes a world's gloves first. Thread: host. */
FRUSTA_API frusta_result frusta_destroy_device(frusta_device_id device);
/** 1 if the id names an open glove, else 0. Thread: any. */
FRUSTA_API int32_t frusta_device_is_valid(frusta_device_id device);
/** The newest status (lock-free; set out->struct_size first). Thread: host. */
FRUSTA_API frusta_result frusta_device_get_status(frusta_device_id device,
                                                  frusta_device_status* out);
/** The palm pose (metres, tracking frame) for a glove without a tracker: the next
 *  samples carry it. Lock-free. Thread: any one thread per device. */
FRUSTA_API frusta_result frusta_device_set_palm_pose(frusta_device_id device,
                                                     const frusta_pose* palm);

#endif /* FRUSTA_FRUSTA_H */
