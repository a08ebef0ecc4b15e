// SPDX-License-Identifier: MIT
// The hand-written C# part: the exception, and the helpers the typemaps of o3d_csharp.i call
// (pinning arrays in, one copy out, static callback trampolines with GCHandle user data).
using System;
using System.Runtime.InteropServices;

namespace O3d
{
    /// <summary>A failed o3d call: the C status (Library.ERROR_*) and o3d_last_error_message().</summary>
    public class O3dException : Exception
    {
        public int Status { get; private set; }
        public O3dException(int status, string message) : base(message) { Status = status; }
    }

    /// <summary>A borrowed view of native memory (the *View methods): valid until its owner changes or is
    /// disposed. Rows as the C API counts them; Bytes = rows x values per row x value size.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct View { public IntPtr Data; public long Rows; public long Bytes; }

    /// <summary>Marks a static method as callable from native code (Mono AOT / IL2CPP).</summary>
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public MonoPInvokeCallbackAttribute(Type delegateType) { DelegateType = delegateType; }
        public Type DelegateType { get; private set; }
    }

    internal static class O3dx
    {
        [StructLayout(LayoutKind.Sequential)]
        internal struct Span { public IntPtr p; public long n; }
        [StructLayout(LayoutKind.Sequential)]
        internal struct OutSpan { public IntPtr p; public long n; public int owned; }

        internal static GCHandle Pin(Array a) { return GCHandle.Alloc(a, GCHandleType.Pinned); }
        internal static Span SpanOf(GCHandle h, Array a)
        {
            return new Span { p = a == null ? IntPtr.Zero : h.AddrOfPinnedObject(), n = a == null ? 0 : a.Length };
        }

        [DllImport("libo3d_csharp")] static extern void o3dx_free(IntPtr p);
        /// <summary>Copies a native result once into <paramref name="a"/> (null when the call failed).</summary>
        internal static T[] Take<T>(OutSpan s, T[] a)
        {
            if (s.p == IntPtr.Zero) return null;
            if (a is double[]) Marshal.Copy(s.p, a as double[], 0, a.Length);
            else if (a is int[]) Marshal.Copy(s.p, a as int[], 0, a.Length);
            else if (a is long[]) Marshal.Copy(s.p, a as long[], 0, a.Length);
            else if (a is float[]) Marshal.Copy(s.p, a as float[], 0, a.Length);
            else Marshal.Copy(s.p, a as byte[], 0, a.Length);
            if (s.owned != 0) o3dx_free(s.p);
            return a;
        }

        /// <summary>A native text result (o3dx_text) as a string; the native copy is freed.</summary>
        internal static string TakeText(IntPtr p) { string s = Marshal.PtrToStringAnsi(p); if (p != IntPtr.Zero) o3dx_free(p); return s; }

        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        delegate int ProgressFn(double fraction, IntPtr userData);
        static readonly ProgressFn progress = Progress; // kept alive: native code holds its pointer
        internal static readonly IntPtr ProgressTrampoline = Marshal.GetFunctionPointerForDelegate(progress);
        [MonoPInvokeCallback(typeof(ProgressFn))]
        static int Progress(double fraction, IntPtr userData)
        {
            try { var f = (Func<double, bool>)GCHandle.FromIntPtr(userData).Target; return f == null || f(fraction) ? 0 : 1; }
            catch (Exception) { return 1; } // an exception cancels: it must not cross native frames
        }

        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        delegate void LogFn(int level, IntPtr message, IntPtr userData);
        static readonly LogFn log = Log;
        internal static readonly IntPtr LogTrampoline = Marshal.GetFunctionPointerForDelegate(log);
        internal static volatile Action<int, string> LogHandler;
        [MonoPInvokeCallback(typeof(LogFn))]
        static void Log(int level, IntPtr message, IntPtr userData)
        {
            var h = LogHandler;
            try { if (h != null) h(level, Marshal.PtrToStringAnsi(message) ?? ""); }
            catch (Exception) { } // a log handler must not throw into native code
        }
    }
}
