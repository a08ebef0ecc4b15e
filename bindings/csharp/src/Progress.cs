// SPDX-License-Identifier: MIT
using System;
using System.Runtime.InteropServices;

namespace O3d
{
    /// <summary>
    /// Passes a managed progress callback (<c>Func&lt;double, bool&gt;</c>: return false to cancel) to native
    /// code through one static trampoline (IL2CPP/AOT friendly) and a GCHandle as user_data.
    /// </summary>
    internal sealed class ProgressBridge : IDisposable
    {
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        internal delegate int ProgressCallbackNative(double fraction, IntPtr userData);

        // Kept in a static field: native code holds its address while a call runs.
        static readonly ProgressCallbackNative trampoline = Trampoline;

        [MonoPInvokeCallback(typeof(ProgressCallbackNative))]
        static int Trampoline(double fraction, IntPtr userData)
        {
            try
            {
                var f = (Func<double, bool>)GCHandle.FromIntPtr(userData).Target;
                return f(fraction) ? 0 : 1;
            }
            catch (Exception) { return 1; } // a throwing callback cancels; nothing unwinds through native frames
        }

        GCHandle pin;

        /// <summary>The function pointer for the options' progress field (IntPtr.Zero without a callback).</summary>
        public IntPtr Function { get; private set; }
        /// <summary>The options' user_data (IntPtr.Zero without a callback).</summary>
        public IntPtr UserData { get; private set; }

        /// <summary>Pins <paramref name="progress"/> (may be null) until Dispose, which must follow the native call.</summary>
        public ProgressBridge(Func<double, bool> progress)
        {
            if (progress == null) return;
            pin = GCHandle.Alloc(progress);
            Function = Marshal.GetFunctionPointerForDelegate(trampoline);
            UserData = GCHandle.ToIntPtr(pin);
        }

        public void Dispose()
        {
            if (pin.IsAllocated) pin.Free();
            Function = IntPtr.Zero;
            UserData = IntPtr.Zero;
        }
    }
}
