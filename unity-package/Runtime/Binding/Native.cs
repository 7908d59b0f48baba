// SPDX-License-Identifier: MIT
// P/Invoke over frusta.h: every FRUSTA_API function, names verbatim (grep finds both
// sides), Cdecl, exact spelling, blittable arguments only (ids and structs by value,
// everything else by pointer), no generic signatures, no delegates: IL2CPP- and AOT-safe.
// C const char* is byte* (UTF-8, NUL-terminated; see Utf8). Results are frusta_result.
using System.Runtime.InteropServices;

namespace Frusta.Binding
{
    internal static unsafe class Native
    {
        const CallingConvention Cdecl = CallingConvention.Cdecl;

        // ---------------------------------------------------------------- version, errors
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern int frusta_version();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern int frusta_abi_version();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern byte* frusta_last_error();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern byte* frusta_result_name(int result);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_check_abi(int headerAbiVersion);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern int frusta_struct_size(byte* name);

        // ---------------------------------------------------------------- hand
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaHandDef frusta_default_hand_def();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_hand_def_set_size(FrustaHandDef* def, double handLength, double handBreadth);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_create_hand(FrustaHandDef* def, FrustaHandId* outHand);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_destroy_hand(FrustaHandId hand);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern int frusta_hand_is_valid(FrustaHandId hand);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_hand_set_palm_pose(FrustaHandId hand, FrustaPose* pose);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_hand_set_joint_angles(FrustaHandId hand, double* angles, int count);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_hand_get_joint_angles(FrustaHandId hand, double* output, int capacity);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_hand_get_segments(FrustaHandId hand, FrustaSegment* output, int capacity, int* outCount);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_hand_get_palm_spheres(FrustaHandId hand, FrustaSphere* output, int capacity, int* outCount);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_hand_point_jacobian(FrustaHandId hand, int finger, int segment, double* localPoint,
                                                                       double* outPoint, double* outJacobian, int capacity);

        // ---------------------------------------------------------------- geometry queries
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_query_contact(FrustaSegment* segment, FrustaSphere* sphere, FrustaContactQuery* output);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_constraint_eval(FrustaSegment* segment, FrustaSphere* sphere, int form, FrustaConstraint* output);

        // ---------------------------------------------------------------- sphere trees
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaBakeDef frusta_default_bake_def();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_bake_sphere_tree(float* vertices, int vertexCount, int* indices, int indexCount,
                                                                    FrustaBakeDef* def, FrustaTreeId* outTree);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_load_sphere_tree(byte* path, FrustaTreeId* outTree);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_save_sphere_tree(FrustaTreeId tree, byte* path);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_destroy_sphere_tree(FrustaTreeId tree);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern int frusta_sphere_tree_is_valid(FrustaTreeId tree);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_sphere_tree_get_info(FrustaTreeId tree, FrustaSphereTreeInfo* info);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_sphere_tree_get_leaves(FrustaTreeId tree, FrustaSphere* output, int capacity, int* outCount);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_sphere_tree_query_segment(FrustaTreeId tree, FrustaPose* pose, FrustaSegment* segment,
                                                                             double margin, int maxLevel, FrustaTreeHit* output,
                                                                             int capacity, int* outCount);

        // ---------------------------------------------------------------- world
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaWorldDef frusta_default_world_def();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaObjectDef frusta_default_object_def();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_create_world(FrustaWorldDef* def, FrustaWorldId* outWorld);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_destroy_world(FrustaWorldId world);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern int frusta_world_is_valid(FrustaWorldId world);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_add_hand(FrustaWorldId world, FrustaHandDef* def, int* outHand);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_set_haptic(FrustaWorldId world, int hand, FrustaPose* palm, double* angles, int count);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_add_object(FrustaWorldId world, FrustaTreeId tree, FrustaObjectDef* def,
                                                                    FrustaObjectId* outObject);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_remove_object(FrustaWorldId world, FrustaObjectId obj);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_set_object_pose(FrustaWorldId world, FrustaObjectId obj, FrustaPose* pose);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_set_object_dynamic(FrustaWorldId world, FrustaObjectId obj, int dynamic);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_step(FrustaWorldId world);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_start(FrustaWorldId world);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_stop(FrustaWorldId world);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_read(FrustaWorldId world, FrustaWorldState* state);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_get_hand(FrustaWorldId world, int hand, FrustaWorldHand* output);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_get_contacts(FrustaWorldId world, int hand, FrustaWorldContact* output, int capacity,
                                                                      int* outCount);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_get_object(FrustaWorldId world, FrustaObjectId obj, FrustaObjectState* output);

        // ---------------------------------------------------------------- devices
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaDeviceDef frusta_default_device_def();
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_enumerate_devices(FrustaDeviceInfo* output, int capacity, int* outCount);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_world_open_device(FrustaWorldId world, byte* uri, FrustaDeviceDef* def,
                                                                     FrustaDeviceId* outDevice);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_device_close(FrustaDeviceId device);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern int frusta_device_is_valid(FrustaDeviceId device);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_device_get_status(FrustaDeviceId device, FrustaDeviceStatus* output);
        [DllImport(Lib.Name, CallingConvention = Cdecl, ExactSpelling = true)]
        internal static extern FrustaResult frusta_device_set_palm_pose(FrustaDeviceId device, FrustaPose* palm);
    }
}
