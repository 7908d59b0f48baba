// SPDX-License-Identifier: MIT
using System;

namespace Frusta.Binding
{
    /// <summary>
    /// A sphere tree: an object's shape for the engine, baked from a triangle mesh or loaded
    /// from a <c>.frtree</c> file. Dispose it when no longer needed; a <see cref="World"/> that
    /// uses it keeps its own reference, so disposing the tree never breaks a world. All
    /// members may be called from any thread, but not while another thread disposes the tree.
    /// </summary>
    public sealed unsafe class SphereTree : IDisposable
    {
        /// <summary>The file extension of baked trees, with its dot.</summary>
        public const string FileExtension = ".frtree";

        readonly TreeHandle handle;

        SphereTree(TreeHandle handle) => this.handle = handle;

        internal TreeHandle Handle => handle;

        /// <summary>The native id (a value; stale once disposed).</summary>
        public FrustaTreeId Id => handle.Id;

        /// <summary>false once disposed or when the native tree is gone (<c>frusta_sphere_tree_is_valid</c>).</summary>
        public bool IsValid => !handle.IsClosed && Native.frusta_sphere_tree_is_valid(handle.Id) == 1;

        /// <summary>Load a <c>.frtree</c> file (<c>frusta_create_sphere_tree_from_file</c>). Thread: any.</summary>
        /// <param name="path">A file path (UTF-8 on the native side).</param>
        /// <returns>The tree; dispose it.</returns>
        /// <exception cref="FrustaException"><see cref="FrustaResult.Io"/> for a missing or unreadable file,
        /// <see cref="FrustaResult.FileFormat"/> or <see cref="FrustaResult.CorruptFile"/> for a bad one,
        /// with the native message naming the problem.</exception>
        public static SphereTree Load(string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            FrustaLibrary.EnsureCompatible();
            var h = new TreeHandle();
            int max = Utf8.MaxBytes(path);
            Span<byte> text = max <= Utf8.StackLimit ? stackalloc byte[max] : new byte[max];
            Utf8.Encode(path, text, nameof(path));
            FrustaTreeId id;
            FrustaResult r;
            fixed (byte* p = text) r = Native.frusta_create_sphere_tree_from_file(p, &id);
            h.Own(r, id, "frusta_create_sphere_tree_from_file");
            return new SphereTree(h);
        }

        /// <summary>Load a tree from a <c>.frtree</c> file's bytes in memory (an engine asset's: no temporary
        /// file; <c>frusta_create_sphere_tree_from_memory</c>), checked as <see cref="Load(string)"/> checks a
        /// file. Thread: any.</summary>
        /// <param name="fileBytes">The whole file.</param>
        /// <returns>The tree; dispose it.</returns>
        /// <exception cref="FrustaException"><see cref="FrustaResult.FileFormat"/> or
        /// <see cref="FrustaResult.CorruptFile"/> for bytes that are not a whole valid tree, with the
        /// native message naming the problem.</exception>
        public static SphereTree LoadFromMemory(ReadOnlySpan<byte> fileBytes)
        {
            FrustaLibrary.EnsureCompatible();
            var h = new TreeHandle();
            FrustaTreeId id;
            FrustaResult r;
            // a pointer to something even for no bytes: an empty span's is null
            byte none = 0;
            fixed (byte* p = fileBytes)
                r = Native.frusta_create_sphere_tree_from_memory(p != null ? p : &none, fileBytes.Length, &id);
            h.Own(r, id, "frusta_create_sphere_tree_from_memory");
            return new SphereTree(h);
        }

        /// <summary>A tree whose id a native call returned (a bake job's), owned from now on.</summary>
        internal static SphereTree Own(FrustaResult r, FrustaTreeId id, string call)
        {
            var h = new TreeHandle();
            h.Own(r, id, call);
            return new SphereTree(h);
        }

        /// <summary>Bake a tree from triangles with the default bake parameters.</summary>
        /// <param name="vertices">xyz triples, metres, right-handed object frame (Frusta's; convert
        /// Unity meshes with <see cref="CoordinateConversion"/>, which also reverses the winding).</param>
        /// <param name="indices">Three per triangle, counter-clockwise seen from outside.</param>
        /// <returns>The tree; dispose it.</returns>
        public static SphereTree Bake(ReadOnlySpan<float> vertices, ReadOnlySpan<int> indices) =>
            Bake(vertices, indices, FrustaBakeDef.Default);

        /// <summary>
        /// Bake a tree from triangles (<c>frusta_create_sphere_tree_from_mesh</c>). Blocks for the bake's
        /// duration (seconds for 10^5 triangles): call it off any frame loop. A target that does not fit
        /// in MaxLeaves is coarsened until the whole object is covered within them, and the tree is
        /// still returned: check <see cref="FrustaSphereTreeInfo.TargetMet"/> and its error figures.
        /// Thread: any; bakes on different threads run concurrently.
        /// </summary>
        /// <param name="vertices">xyz triples, metres, right-handed object frame.</param>
        /// <param name="indices">Three per triangle, counter-clockwise seen from outside.</param>
        /// <param name="def">From <see cref="FrustaBakeDef.Default"/>, then edited.</param>
        /// <returns>The tree; dispose it.</returns>
        /// <exception cref="FrustaException">Bad parameters or a degenerate mesh, with the native message.</exception>
        public static SphereTree Bake(ReadOnlySpan<float> vertices, ReadOnlySpan<int> indices, in FrustaBakeDef def)
        {
            if (vertices.Length % 3 != 0) throw new ArgumentException("must hold xyz triples", nameof(vertices));
            FrustaLibrary.EnsureCompatible();
            var h = new TreeHandle();
            FrustaTreeId id;
            FrustaResult r;
            fixed (float* v = vertices)
            fixed (int* i = indices)
            fixed (FrustaBakeDef* d = &def)
                r = Native.frusta_create_sphere_tree_from_mesh(v, vertices.Length / 3, i, indices.Length, d, &id);
            h.Own(r, id, "frusta_create_sphere_tree_from_mesh");
            return new SphereTree(h);
        }

        /// <summary>Write the tree to <paramref name="path"/> atomically (a reader never sees half a
        /// file; <c>frusta_sphere_tree_save</c>). Thread: any.</summary>
        /// <param name="path">A file path.</param>
        /// <exception cref="FrustaException"><see cref="FrustaResult.Io"/> when the file cannot be written.</exception>
        public void Save(string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            int max = Utf8.MaxBytes(path);
            Span<byte> text = max <= Utf8.StackLimit ? stackalloc byte[max] : new byte[max];
            Utf8.Encode(path, text, nameof(path));
            using (new HandleUse(handle))
            fixed (byte* p = text)
                Errors.Check(Native.frusta_sphere_tree_save(handle.Id, p), "frusta_sphere_tree_save");
        }

        /// <summary>What the tree holds and how well it fits its mesh (<c>frusta_sphere_tree_get_info</c>).
        /// Allocation-free. Thread: any.</summary>
        public FrustaSphereTreeInfo Info
        {
            get
            {
                var info = new FrustaSphereTreeInfo { struct_size = sizeof(FrustaSphereTreeInfo) };
                using (new HandleUse(handle))
                    Errors.Check(Native.frusta_sphere_tree_get_info(handle.Id, &info), "frusta_sphere_tree_get_info");
                return info;
            }
        }

        /// <summary>The number of leaf spheres.</summary>
        public int LeafCount => GetLeaves(default);

        /// <summary>Copy the leaf spheres (object frame, metres) in their stable numbering: the first
        /// min(destination.Length, <see cref="LeafCount"/>) (<c>frusta_sphere_tree_get_leaves</c>). Thread: any.</summary>
        /// <param name="destination">Receives the leaves; <see cref="LeafCount"/> holds all.</param>
        /// <returns>How many leaves the tree has, which exceeds destination.Length when it was short.</returns>
        public int GetLeaves(Span<FrustaSphere> destination) =>
            handle.CopyOut(destination, (id, p, capacity, count) => Native.frusta_sphere_tree_get_leaves(id, p, capacity, count),
                           "frusta_sphere_tree_get_leaves");

        /// <summary>
        /// Every leaf (or, with <paramref name="maxLevel"/> &gt;= 0, every node at that level) within
        /// <paramref name="margin"/> metres of a world segment, for the object placed at
        /// <paramref name="pose"/> (<c>frusta_sphere_tree_query_segment</c>). Thread: any.
        /// </summary>
        /// <param name="pose">Where the object is, world frame.</param>
        /// <param name="segment">A segment in the world frame.</param>
        /// <param name="margin">Metres, &gt;= 0.</param>
        /// <param name="maxLevel">-1 for leaves, else the level whose nodes stand in for their subtrees.</param>
        /// <param name="hits">Receives at most its length of hits.</param>
        /// <returns>The number found, which may exceed hits.Length.</returns>
        public int QuerySegment(in FrustaPose pose, in FrustaSegment segment, double margin, int maxLevel, Span<FrustaTreeHit> hits)
        {
            int count;
            using (new HandleUse(handle))
            fixed (FrustaPose* p = &pose)
            fixed (FrustaSegment* s = &segment)
            fixed (FrustaTreeHit* h = hits)
                Errors.Check(Native.frusta_sphere_tree_query_segment(handle.Id, p, s, margin, maxLevel, h, hits.Length, &count),
                             "frusta_sphere_tree_query_segment");
            return count;
        }

        /// <summary>Destroy the native tree (<c>frusta_destroy_sphere_tree</c>); worlds using it keep
        /// it alive. Safe to call twice.</summary>
        public void Dispose() => handle.Dispose();
    }
}
