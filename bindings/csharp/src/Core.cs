// SPDX-License-Identifier: MIT
// O3d: idiomatic C# layer over the SWIG-generated raw module (O3dNative, internal).
// Errors: every non-OK o3d_status becomes an O3dException (raised by the shared SWIG typemap).
using System;
using System.Runtime.InteropServices;

namespace O3d
{
    /// <summary>Status codes of the C API (o3d_status).</summary>
    public enum Status
    {
        Ok = O3dNative.O3D_OK,
        InvalidArgument = O3dNative.O3D_ERROR_INVALID_ARGUMENT,
        OutOfMemory = O3dNative.O3D_ERROR_OUT_OF_MEMORY,
        IO = O3dNative.O3D_ERROR_IO,
        Parse = O3dNative.O3D_ERROR_PARSE,
        Unsupported = O3dNative.O3D_ERROR_UNSUPPORTED,
        BufferTooSmall = O3dNative.O3D_ERROR_BUFFER_TOO_SMALL,
        NotConverged = O3dNative.O3D_ERROR_NOT_CONVERGED,
        Cancelled = O3dNative.O3D_ERROR_CANCELLED,
        Internal = O3dNative.O3D_ERROR_INTERNAL,
    }

    /// <summary>Log levels, most severe first.</summary>
    public enum LogLevel
    {
        Error = O3dNative.O3D_LOG_ERROR,
        Warning = O3dNative.O3D_LOG_WARNING,
        Info = O3dNative.O3D_LOG_INFO,
        Debug = O3dNative.O3D_LOG_DEBUG,
    }

    /// <summary>A failed o3d call: the status and o3d_last_error_message() of that call.</summary>
    public class O3dException : Exception
    {
        public Status Status { get; private set; }
        public int Code { get { return (int)Status; } }

        public O3dException(int status, string message)
            : base(O3dNative.o3d_status_string(status) + ": " + message)
        {
            Status = (Status)status;
        }
    }

    /// <summary>Marks static callbacks handed to native code (recognised by name by Unity IL2CPP / Xamarin AOT).</summary>
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public Type DelegateType { get; private set; }
        public MonoPInvokeCallbackAttribute(Type delegateType) { DelegateType = delegateType; }
    }

    internal static class Checks
    {
        /// <summary>Rows of an (N x 3) row-major array; throws when its length is not a multiple of 3.</summary>
        internal static ulong Rows3(Array values, string name)
        {
            if (values == null) throw new ArgumentNullException(name);
            if (values.Length % 3 != 0)
                throw new ArgumentException(name + ": length " + values.Length + " is not a multiple of 3", name);
            return (ulong)(values.Length / 3);
        }

        /// <summary><paramref name="values"/> cut to the <paramref name="n"/> items a copy-out call reported.</summary>
        internal static int[] Trim(int[] values, ulong n)
        {
            if (n >= (ulong)values.Length) return values;
            var r = new int[n];
            Array.Copy(values, r, (long)n);
            return r;
        }

        /// <summary>Pairs in a flattened (source, target) index array; throws when it is null or of odd length.</summary>
        internal static ulong Pairs(int[] pairs, string name)
        {
            if (pairs == null) throw new ArgumentNullException(name);
            if (pairs.Length % 2 != 0)
                throw new ArgumentException(name + ": length " + pairs.Length + " is not a multiple of 2", name);
            return (ulong)(pairs.Length / 2);
        }

        /// <summary>A count or index (&gt;= 0) as the C API's size_t; throws ArgumentOutOfRangeException when negative.</summary>
        internal static ulong Count(long value, string name)
        {
            if (value < 0) throw new ArgumentOutOfRangeException(name, value, name + " must be >= 0");
            return (ulong)value;
        }

        internal static double[] Fixed(double[] values, int length, string name, bool nullable)
        {
            if (values == null)
            {
                if (nullable) return null;
                throw new ArgumentNullException(name);
            }
            if (values.Length != length)
                throw new ArgumentException(name + ": expected " + length + " values, got " + values.Length, name);
            return values;
        }
    }

    /// <summary>Library-wide functions: version, errors, logging, threads.</summary>
    public static class Library
    {
        public static string Version { get { return O3dNative.o3d_version(); } }
        public static int VersionMajor { get { return O3dNative.o3d_version_major(); } }
        public static int VersionMinor { get { return O3dNative.o3d_version_minor(); } }
        public static int VersionPatch { get { return O3dNative.o3d_version_patch(); } }

        /// <summary>Message of the last failure on this thread ("" when none).</summary>
        public static string LastErrorMessage { get { return O3dNative.o3d_last_error_message(); } }
        /// <summary>Status of the last failure on this thread (Ok when none).</summary>
        public static Status LastErrorCode { get { return (Status)O3dNative.o3d_last_error_code(); } }
        public static void ClearError() { O3dNative.o3d_clear_error(); }
        /// <summary>Static name of a status code ("O3D_ERROR_IO", ...).</summary>
        public static string StatusString(Status status) { return O3dNative.o3d_status_string((int)status); }

        public static LogLevel VerbosityLevel
        {
            get { return (LogLevel)O3dNative.o3d_get_verbosity_level(); }
            set { O3dNative.o3d_set_verbosity_level((int)value); }
        }

        /// <summary>Default thread count of parallel calls (0 restores the OpenMP default).</summary>
        public static int NumThreads
        {
            get { return O3dNative.o3d_get_num_threads(); }
            set { O3dNative.o3d_set_num_threads(value); }
        }

        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        internal delegate void LogCallbackNative(int level, IntPtr message, IntPtr userData);

        // Static trampoline (no instance delegate crosses to native code: IL2CPP/AOT friendly),
        // kept alive by this static field for as long as it may be registered.
        static readonly LogCallbackNative logTrampoline = LogTrampoline;
        static Action<LogLevel, string> logHandler;

        [MonoPInvokeCallback(typeof(LogCallbackNative))]
        static void LogTrampoline(int level, IntPtr message, IntPtr userData)
        {
            var handler = logHandler;
            if (handler == null) return;
            try { handler((LogLevel)level, Marshal.PtrToStringAnsi(message) ?? ""); }
            catch (Exception) { /* exceptions must not unwind through native frames */ }
        }

        /// <summary>
        /// Route the library's log lines to <paramref name="handler"/> (called on the logging thread);
        /// null restores the default sink (stderr).
        /// </summary>
        public static void SetLogHandler(Action<LogLevel, string> handler)
        {
            if (handler == null)
            {
                O3dNative.o3d_set_log_callback(IntPtr.Zero, IntPtr.Zero);
                logHandler = null;
                return;
            }
            logHandler = handler;
            O3dNative.o3d_set_log_callback(Marshal.GetFunctionPointerForDelegate(logTrampoline), IntPtr.Zero);
        }
    }

    /// <summary>Neighbourhood search parameter (KDTreeSearchParamKNN / Radius / Hybrid).</summary>
    public sealed class SearchParam
    {
        public enum SearchKind { Knn = O3dNative.O3D_SEARCH_KNN, Radius = O3dNative.O3D_SEARCH_RADIUS, Hybrid = O3dNative.O3D_SEARCH_HYBRID }

        public SearchKind Kind { get; private set; }
        public int MaxNN { get; private set; }
        public double Radius { get; private set; }

        SearchParam(SearchKind kind, int knn, double radius) { Kind = kind; MaxNN = knn; Radius = radius; }

        /// <summary>The <paramref name="knn"/> nearest points (KDTreeSearchParamKNN).</summary>
        public static SearchParam Knn(int knn = 30) { return new SearchParam(SearchKind.Knn, knn, 0.0); }
        /// <summary>All points within <paramref name="radius"/> (KDTreeSearchParamRadius).</summary>
        public static SearchParam RadiusSearch(double radius) { return new SearchParam(SearchKind.Radius, 0, radius); }
        /// <summary>At most <paramref name="maxNN"/> nearest points within <paramref name="radius"/> (KDTreeSearchParamHybrid).</summary>
        public static SearchParam Hybrid(double radius, int maxNN) { return new SearchParam(SearchKind.Hybrid, maxNN, radius); }

        /// <summary>A native o3d_search_param_t filled by o3d_search_param_init; the caller disposes it.</summary>
        internal o3d_search_param_t ToNative()
        {
            var p = new o3d_search_param_t();
            O3dNative.o3d_search_param_init(p, O3dNative.o3dx_sizeof_search_param());
            p.kind = (int)Kind;
            p.knn = MaxNN;
            p.radius = Radius;
            return p;
        }
    }

    /// <summary>Owned native handle with Dispose + finalizer; base of PointCloud, KDTreeFlann, SearchResult, NativeBuffer.</summary>
    public abstract class NativeHandle : IDisposable
    {
        IntPtr handle;

        internal NativeHandle(IntPtr handle)
        {
            if (handle == IntPtr.Zero) throw new O3dException((int)Status.Internal, "null handle");
            this.handle = handle;
        }

        /// <summary>The raw o3d handle (for interop). Throws ObjectDisposedException after Dispose.</summary>
        public IntPtr Handle
        {
            get
            {
                if (handle == IntPtr.Zero) throw new ObjectDisposedException(GetType().Name);
                return handle;
            }
        }

        public bool IsDisposed { get { return handle == IntPtr.Zero; } }

        internal abstract void Destroy(IntPtr handle);

        /// <summary>Destroys the native object. Idempotent.</summary>
        public void Dispose()
        {
            Dispose(true);
            GC.SuppressFinalize(this);
        }

        void Dispose(bool disposing)
        {
            IntPtr h = handle;
            handle = IntPtr.Zero;
            if (h != IntPtr.Zero) Destroy(h);
        }

        /// <summary>Safety net: objects not disposed are destroyed by the finalizer.</summary>
        ~NativeHandle() { Dispose(false); }
    }
}
