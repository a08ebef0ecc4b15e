/* SPDX-License-Identifier: MIT */
/*
 * C#-only typemaps for bindings/swig/o3d.i (included from there). Arrays are pinned (GCHandle),
 * never copied in; results are copied once (O3dx.cs). Errors reach O3dException through one
 * registered managed callback; callbacks run through static trampolines + GCHandle user_data
 * (no directors: IL2CPP-compatible).
 */
%csconst(1);
%typemap(csinterfaces) SWIGTYPE "global::System.IDisposable"
%typemap(csclassmodifiers) SWIGTYPE "public partial class" /* conveniences: bindings/csharp/src/*.cs */
%typemap(cscode) SWIGTYPE %{
  /// <summary>True once Dispose ran (later calls throw ObjectDisposedException).</summary>
  public bool IsDisposed { get { return swigCPtr.Handle == global::System.IntPtr.Zero; } }
%}

%{
typedef struct { const void *p; int64_t n; } o3dx_span;
typedef struct { void *p; int64_t n; int32_t owned; } o3dx_ospan;
static const o3dx_ospan o3dx_ospan_null;
SWIGEXPORT void SWIGSTDCALL o3dx_free(void *p) { free(p); }
#define o3dx_struct_free_plain(s, _) free(s)
#define o3dx_struct_free_progress(s, _) free(s) /* the managed side frees its GCHandle */
%}

/* ---- arrays in: pinned managed arrays ------------------------------------------------------- */
%define O3DX_CS_IN(E, CSTYPE)
%typemap(ctype) o3dx_in_##E "o3dx_span"
%typemap(imtype) o3dx_in_##E "O3dx.Span"
%typemap(cstype) o3dx_in_##E "CSTYPE[]"
%typemap(csin, pre="    var pin_$csinput = O3dx.Pin($csinput);", post="      pin_$csinput.Free();")
  o3dx_in_##E "O3dx.SpanOf(pin_$csinput, $csinput)"
%typemap(in) o3dx_in_##E %{ $1.p = $input.p; $1.n = (size_t)$input.n; %}
%enddef
O3DX_CS_IN(f64, double)
O3DX_CS_IN(f32, float)
O3DX_CS_IN(i32, int)
O3DX_CS_IN(i64, long)
O3DX_CS_IN(u8, byte)
/* correspondence checkers: an array of proxies, copied into one contiguous C array */
%typemap(ctype) o3dx_in_o3d_correspondence_checker_t "o3dx_span"
%typemap(imtype) o3dx_in_o3d_correspondence_checker_t "O3dx.Span"
%typemap(cstype) o3dx_in_o3d_correspondence_checker_t "CorrespondenceChecker[]"
%typemap(csin, pre="    var pin_$csinput = O3dx.Pin($csinput == null ? null : global::System.Array.ConvertAll($csinput, c => CorrespondenceChecker.getCPtr(c).Handle));",
  post="      pin_$csinput.Free();") o3dx_in_o3d_correspondence_checker_t "O3dx.SpanOf(pin_$csinput, $csinput)"
%typemap(in) o3dx_in_o3d_correspondence_checker_t (o3d_correspondence_checker_t *tmp = NULL) %{
  $1.n = (size_t)$input.n;
  if ($1.n) {
    size_t i;
    tmp = (o3d_correspondence_checker_t *)malloc($1.n * sizeof *tmp);
    for (i = 0; tmp && i < $1.n; ++i) tmp[i] = *((o3d_correspondence_checker_t *const *)$input.p)[i];
  }
  $1.p = tmp;
%}
%typemap(freearg) o3dx_in_o3d_correspondence_checker_t %{ free(tmp$argnum); %}

/* arrays of handles: an array of proxies, its handles pinned as one IntPtr[] (a null element is a NULL handle);
   the proxies are kept alive until the call returns */
%define O3DX_HANDLES_IN(T, CLS)
%typemap(ctype) o3dx_handles_##T "o3dx_span"
%typemap(imtype) o3dx_handles_##T "O3dx.Span"
%typemap(cstype) o3dx_handles_##T "CLS[]"
%typemap(csin, pre="    var pin_$csinput = O3dx.Pin($csinput == null ? null : global::System.Array.ConvertAll($csinput, c => CLS.getCPtr(c).Handle));",
  post="      pin_$csinput.Free();\n      global::System.GC.KeepAlive($csinput);") o3dx_handles_##T "O3dx.SpanOf(pin_$csinput, $csinput)"
%typemap(in) o3dx_handles_##T %{ $1.p = (const T *const *)$input.p; $1.n = (size_t)$input.n; %}
%enddef

/* ---- arrays out: one copy into a new managed array ------------------------------------------ */
%define O3DX_CS_OUT(E, CSTYPE)
%typemap(ctype) o3dx_out_##E "o3dx_ospan"
%typemap(imtype) o3dx_out_##E "O3dx.OutSpan"
%typemap(cstype) o3dx_out_##E "CSTYPE[]"
%typemap(out, null="o3dx_ospan_null") o3dx_out_##E %{ $result.p = $1.p; $result.n = (int64_t)$1.n; $result.owned = $1.owned; %}
%typemap(csout, excode=SWIGEXCODE) o3dx_out_##E {
    var span = $imcall;
    var ret = O3dx.Take(span, new CSTYPE[span.p == global::System.IntPtr.Zero ? 0 : span.n]);$excode
    return ret;
  }
%enddef
O3DX_CS_OUT(f64, double)
O3DX_CS_OUT(f32, float)
O3DX_CS_OUT(i32, int)
O3DX_CS_OUT(i64, long)
O3DX_CS_OUT(u8, byte)

/* ---- views: borrowed native memory (O3d.View: Data, Rows, Bytes) ------------------------------ */
%typemap(ctype, out="o3dx_view") o3dx_view, o3dx_mview "o3dx_view"
%typemap(imtype) o3dx_view, o3dx_mview "View"
%typemap(cstype) o3dx_view, o3dx_mview "View"
%typemap(out, null="o3dx_view_null") o3dx_view, o3dx_mview %{ $result = $1; %}
%typemap(csout, excode=SWIGEXCODE) o3dx_view, o3dx_mview {
    var v = $imcall;$excode
    return v;
  }

/* text results (o3dx_text): one managed string; the native copy is freed */
%typemap(ctype) o3dx_text "char *"
%typemap(imtype) o3dx_text "global::System.IntPtr"
%typemap(cstype) o3dx_text "string"
%typemap(out) o3dx_text %{ $result = $1; %}
%typemap(csout, excode=SWIGEXCODE) o3dx_text {
    string ret = O3dx.TakeText($imcall);$excode
    return ret;
  }

/* raw pointers (callback trampolines, user_data) */
%typemap(ctype) void * "void *"
%typemap(imtype) void * "global::System.IntPtr"
%typemap(cstype) void * "global::System.IntPtr"
%typemap(in) void * %{ $1 = $input; %}
%typemap(csin) void * "$csinput"

/* ---- IL2CPP: no reverse P/Invoke without [MonoPInvokeCallback] ---------------------------------
 * SWIG's own exception and string helpers hand static methods without that attribute to native code,
 * which IL2CPP refuses; bindings/swig/CMakeLists.txt turns them off (SWIG_CSHARP_NO_EXCEPTION_HELPER,
 * SWIG_CSHARP_NO_STRING_HELPER). Errors come through O3dExceptionHelper below instead, and a returned
 * `const char *` (borrowed from the library) is copied into a managed string on the managed side. */
%typemap(imtype, out="global::System.IntPtr") char *, char *& "string"
%typemap(out) char * %{ $result = $1; %}
%typemap(csout, excode=SWIGEXCODE) char * {
    string ret = global::System.Runtime.InteropServices.Marshal.PtrToStringAnsi($imcall);$excode
    return ret;
  }

/* ---- errors --------------------------------------------------------------------------------- */
%insert(runtime) %{
typedef void (SWIGSTDCALL *o3dcs_raise_callback)(int status, const char *message);
static o3dcs_raise_callback o3dcs_raise = 0;
SWIGEXPORT void SWIGSTDCALL O3dCsRegisterExceptionCallback(o3dcs_raise_callback callback) { o3dcs_raise = callback; }
#define O3D_SWIG_RAISE(status, message) do { if (o3dcs_raise) o3dcs_raise((int)(status), (message)); } while (0)
%}
%pragma(csharp) imclasscode=%{
  internal class O3dExceptionHelper {
    [global::System.Runtime.InteropServices.UnmanagedFunctionPointer(global::System.Runtime.InteropServices.CallingConvention.Cdecl)]
    public delegate void RaiseDelegate(int status, [global::System.Runtime.InteropServices.MarshalAs(global::System.Runtime.InteropServices.UnmanagedType.LPStr)] string message);
    static RaiseDelegate raiseDelegate = new RaiseDelegate(Raise); // the native side keeps a pointer to it
    [global::System.Runtime.InteropServices.DllImport("$dllimport", EntryPoint="O3dCsRegisterExceptionCallback")]
    public static extern void O3dCsRegisterExceptionCallback(RaiseDelegate callback);
    [O3d.MonoPInvokeCallback(typeof(RaiseDelegate))]
    static void Raise(int status, string message) {
      if (SWIGPendingException.Pending) return; // a callback's own exception (src/Visualizer.cs) wins
      SWIGPendingException.Set(status == -1000 ? (global::System.Exception)new global::System.ObjectDisposedException(message)
                                               : new O3d.O3dException(status, message));
    }
    static O3dExceptionHelper() { O3dCsRegisterExceptionCallback(raiseDelegate); }
  }
  static O3dExceptionHelper o3dExceptionHelper = new O3dExceptionHelper();

  /// <summary>The exception a failed call left for its thread; every wrapper throws it when the call returns.</summary>
  public class SWIGPendingException {
    [global::System.ThreadStatic] static global::System.Exception pending;
    public static bool Pending { get { return pending != null; } }
    public static void Set(global::System.Exception e) { pending = e; }
    public static global::System.Exception Retrieve() { var e = pending; pending = null; return e; }
  }
%}

/* ---- callbacks: progress (options structs), log, Visualizer (src/Visualizer.cs) ----------------- */
/* Dispose: the native object, then RELEASE (its callbacks' GCHandles) */
%define O3DX_CS_DISPOSING(T, RELEASE)
%typemap(csdisposing, methodname="Dispose", methodmodifiers="protected", parameters="bool disposing") T {
    lock(this) {
      if (swigCPtr.Handle != global::System.IntPtr.Zero) {
        if (swigCMemOwn) {
          swigCMemOwn = false;
          $imcall;
        }
        swigCPtr = new global::System.Runtime.InteropServices.HandleRef(null, global::System.IntPtr.Zero);
      }
      RELEASE;
    }
  }
%enddef
%define O3DX_PROGRESS(T)
%csmethodmodifiers T::set_progress_native "internal"; /* before the %extend, or it stays public */
%extend T { void set_progress_native(void *fn, void *user_data) { $self->progress = (o3d_progress_callback)fn; $self->user_data = user_data; } }
%typemap(cscode) T %{
  // The delegate lives in this field; native code gets a WEAK handle to it, so a callback that captures
  // this options object makes no GC root cycle: an options object never disposed is still finalized.
  global::System.Func<double, bool> progressFn;
  global::System.Runtime.InteropServices.GCHandle progressHandle;
  /// <summary>Called with the fraction done; return false to cancel (the call throws O3dException CANCELLED).</summary>
  public void SetProgress(global::System.Func<double, bool> progress) {
    global::System.Runtime.InteropServices.GCHandle old = progressHandle;
    progressFn = progress;
    progressHandle = progress == null ? default(global::System.Runtime.InteropServices.GCHandle)
                                      : global::System.Runtime.InteropServices.GCHandle.Alloc(progress, global::System.Runtime.InteropServices.GCHandleType.Weak);
    SetProgressNative(progress == null ? global::System.IntPtr.Zero : O3dx.ProgressTrampoline,
                      progress == null ? global::System.IntPtr.Zero : global::System.Runtime.InteropServices.GCHandle.ToIntPtr(progressHandle));
    if (old.IsAllocated) old.Free();
  }
  public bool IsDisposed { get { return swigCPtr.Handle == global::System.IntPtr.Zero; } }
  /// <summary>The progress callback (see SetProgress).</summary>
  public global::System.Func<double, bool> Progress { get { return progressFn; } set { SetProgress(value); } }
%}
O3DX_CS_DISPOSING(T, if (progressHandle.IsAllocated) progressHandle.Free())
%enddef

%inline %{
static void set_log_callback_native(void *fn) { o3d_set_log_callback((o3d_log_callback)fn, NULL); }
%}
%csmethodmodifiers set_log_callback_native "internal";
%pragma(csharp) modulecode=%{
  /// <summary>Send o3d's log lines to <paramref name="handler"/> (level, message); null restores stderr.</summary>
  public static void SetLogHandler(global::System.Action<int, string> handler) {
    O3dx.LogHandler = handler;
    SetLogCallbackNative(handler == null ? global::System.IntPtr.Zero : O3dx.LogTrampoline);
  }
%}
O3DX_CS_DISPOSING(o3d_visualizer_t, ReleaseCallbacks())
%csmethodmodifiers o3d_visualizer_t::register_native "internal";
%csmethodmodifiers o3d_visualizer_t::play_view_trajectory_native "internal";
%extend o3d_visualizer_t {
  void register_native(int32_t kind, int32_t key, void *fn, void *user_data) { o3dx_err = o3dx_visualizer_register($self, kind, key, (void (*)(void))fn, user_data); }
  void play_view_trajectory_native(const char *trajectory_path, const char *capture_dir, int32_t capture_depth, void *fn, void *user_data) {
    o3dx_err = o3d_visualizer_play_view_trajectory($self, trajectory_path, capture_dir, capture_depth, (o3d_progress_callback)fn, user_data);
  }
}
