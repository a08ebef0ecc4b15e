// SPDX-License-Identifier: MIT
// The Visualizer's callbacks: static [MonoPInvokeCallback] trampolines (IL2CPP) with a GCHandle as user data,
// registered through register_native (o3d_csharp.i). A callback's exception stops the loop
// (o3d_visualizer_set_callback_error) and is thrown by the Run / PollEvents / Send* call that ran it.
using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;

namespace O3d
{
    public partial class Visualizer
    {
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int AnimationFn(IntPtr vis, IntPtr userData);
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)] delegate int KeyFn(IntPtr vis, int action, int mods, IntPtr userData);
        static readonly AnimationFn animationFn = OnAnimation; // kept alive: native code holds their pointers
        static readonly KeyFn keyFn = OnKey;
        static readonly IntPtr[] trampolines = { Marshal.GetFunctionPointerForDelegate(animationFn), Marshal.GetFunctionPointerForDelegate(keyFn) };
        // The callbacks by key (-1: animation) live here; native code gets WEAK handles to them, so a callback that
        // captures this visualizer makes no GC root (as the options' progress callbacks).
        readonly Dictionary<int, KeyValuePair<Func<int, int, bool>, GCHandle>> callbacks = new Dictionary<int, KeyValuePair<Func<int, int, bool>, GCHandle>>();

        /// <summary>Called once per loop of Run; true when the geometry or the view changed. null removes it.</summary>
        public void RegisterAnimationCallback(Func<Visualizer, bool> f) { Register(0, -1, f == null ? null : (Func<int, int, bool>)((a, m) => f(this))); }
        /// <summary>Called on press and repeat of <paramref name="key"/> ('A' = 65, Library.KEY_*) instead of o3d's binding.</summary>
        public void RegisterKeyCallback(int key, Func<Visualizer, bool> f) { Register(1, key, f == null ? null : (Func<int, int, bool>)((a, m) => f(this))); }
        /// <summary>As RegisterKeyCallback, also on release; with the action (KEY_ACTION_*) and modifiers (KEY_MOD_*).</summary>
        public void RegisterKeyActionCallback(int key, Func<Visualizer, int, int, bool> f) { Register(2, key, f == null ? null : (Func<int, int, bool>)((a, m) => f(this, a, m))); }

        void Register(int kind, int key, Func<int, int, bool> fn)
        {
            var h = fn == null ? default(GCHandle) : GCHandle.Alloc(fn, GCHandleType.Weak);
            try { RegisterNative(kind, key, fn == null ? IntPtr.Zero : trampolines[Math.Min(kind, 1)], fn == null ? IntPtr.Zero : GCHandle.ToIntPtr(h)); }
            catch { if (h.IsAllocated) h.Free(); throw; }
            KeyValuePair<Func<int, int, bool>, GCHandle> old;
            if (callbacks.TryGetValue(kind == 0 ? -1 : key, out old)) old.Value.Free();
            callbacks.Remove(kind == 0 ? -1 : key);
            if (fn != null) callbacks[kind == 0 ? -1 : key] = new KeyValuePair<Func<int, int, bool>, GCHandle>(fn, h);
        }
        void ReleaseCallbacks() // from Dispose, once the native visualizer is gone
        {
            foreach (var c in callbacks.Values) c.Value.Free();
            callbacks.Clear();
        }

        /// <summary>Plays a ViewTrajectory JSON file, capturing image_%06d.png (and depth_%06d.png) into
        /// <paramref name="captureDir"/> unless null; <paramref name="progress"/> returning false cancels.</summary>
        public void PlayViewTrajectory(string trajectoryPath, string captureDir = null, bool captureDepth = false, Func<double, bool> progress = null)
        {
            var h = progress == null ? default(GCHandle) : GCHandle.Alloc(progress);
            try { PlayViewTrajectoryNative(trajectoryPath, captureDir, captureDepth ? 1 : 0, progress == null ? IntPtr.Zero : O3dx.ProgressTrampoline, progress == null ? IntPtr.Zero : GCHandle.ToIntPtr(h)); }
            finally { if (h.IsAllocated) h.Free(); }
        }

        [MonoPInvokeCallback(typeof(AnimationFn))]
        static int OnAnimation(IntPtr vis, IntPtr userData) { return OnKey(vis, 0, 0, userData); }
        [MonoPInvokeCallback(typeof(KeyFn))]
        static int OnKey(IntPtr vis, int action, int mods, IntPtr userData)
        {
            if (LibraryPINVOKE.SWIGPendingException.Pending) return 0; // a callback failed: the loop is ending
            try { var fn = (Func<int, int, bool>)GCHandle.FromIntPtr(userData).Target; return fn != null && fn(action, mods) ? 1 : 0; }
            catch (Exception e) // must not cross native frames: reported, then thrown by the call that ran the loop
            {
                new Visualizer(vis, false).SetCallbackError(e.GetType().Name + ": " + e.Message);
                LibraryPINVOKE.SWIGPendingException.Set(e);
                return 0;
            }
        }
    }
}
