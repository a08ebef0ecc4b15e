/* SPDX-License-Identifier: MIT */
/*
 * C#-only typemaps for bindings/swig/o3d.i (included from there; never processed alone).
 * Defines the abstract typemap names the shared interface applies, and O3D_SWIG_RAISE.
 */

%include <arrays_csharp.i>
%include <typemaps.i>

/* SWIG 4.1 maps size_t to a 32-bit uint in C#; o3d counts are 64-bit. */
%apply unsigned long long { size_t };
/* SWIG runs with -DSWIGWORDSIZE64 (int64_t = C long), and C# maps C long to 32 bits: be explicit. */
%apply unsigned long long { uint64_t };
%apply long long { int64_t };
/* #define constants as C# compile-time constants. */
%csconst(1);

/* The raw module class is not public: the hand-written O3d.* classes are the API. */
%pragma(csharp) moduleclassmodifiers="internal class"
%typemap(csclassmodifiers) SWIGTYPE "internal class"

/* ---- arrays: one managed array per call (blittable: pinned by the marshaller, no copy) ------ */
%define O3D_CS_ARRAY(CTYPE, BASE)
%apply BASE INPUT[] { const CTYPE *O3D_IN }
%apply BASE OUTPUT[] { CTYPE *O3D_OUT }
%enddef
O3D_CS_ARRAY(double, double)
O3D_CS_ARRAY(float, float)
O3D_CS_ARRAY(int32_t, int)
/* int64_t: explicit (arrays_csharp.i maps C `long` to a 32-bit C# int; SWIG runs with -DSWIGWORDSIZE64) */
%typemap(ctype) int64_t *O3D_OUT "int64_t *"
%typemap(imtype, inattributes="[global::System.Runtime.InteropServices.Out, global::System.Runtime.InteropServices.MarshalAs(global::System.Runtime.InteropServices.UnmanagedType.LPArray)]") int64_t *O3D_OUT "long[]"
%typemap(cstype) int64_t *O3D_OUT "long[]"
%typemap(in) int64_t *O3D_OUT %{ $1 = ($1_ltype)$input; %}
%typemap(csin) int64_t *O3D_OUT "$csinput"
%typemap(ctype) const int64_t *O3D_IN "const int64_t *"
%typemap(imtype, inattributes="[global::System.Runtime.InteropServices.In, global::System.Runtime.InteropServices.MarshalAs(global::System.Runtime.InteropServices.UnmanagedType.LPArray)]") const int64_t *O3D_IN "long[]"
%typemap(cstype) const int64_t *O3D_IN "long[]"
%typemap(in) const int64_t *O3D_IN %{ $1 = ($1_ltype)$input; %}
%typemap(csin) const int64_t *O3D_IN "$csinput"
O3D_CS_ARRAY(uint8_t, unsigned char)

/* ---- scalar outputs: `out T` --------------------------------------------------------------- */
%apply unsigned long long *OUTPUT { size_t *O3D_SOUT }
%apply int *OUTPUT { int32_t *O3D_SOUT }
%apply double *OUTPUT { double *O3D_SOUT }

/* ---- raw pointers (handles, void*, function pointers): IntPtr ------------------------------ */
%typemap(ctype) SWIGTYPE *O3D_PTR "void *"
%typemap(imtype) SWIGTYPE *O3D_PTR "global::System.IntPtr"
%typemap(cstype) SWIGTYPE *O3D_PTR "global::System.IntPtr"
%typemap(in) SWIGTYPE *O3D_PTR %{ $1 = ($1_ltype)$input; %}
%typemap(out) SWIGTYPE *O3D_PTR %{ $result = (void *)$1; %}
%typemap(csin) SWIGTYPE *O3D_PTR "$csinput"
%typemap(csout, excode=SWIGEXCODE) SWIGTYPE *O3D_PTR {
    global::System.IntPtr ret = $imcall;$excode
    return ret;
  }
%typemap(csvarin, excode=SWIGEXCODE2) SWIGTYPE *O3D_PTR %{
    set {
      $imcall;$excode
    } %}
%typemap(csvarout, excode=SWIGEXCODE2) SWIGTYPE *O3D_PTR %{
    get {
      global::System.IntPtr ret = $imcall;$excode
      return ret;
    } %}

/* ---- pointer outputs (`T** out`: owned handles and borrowed views): out IntPtr ------------- */
%typemap(ctype) SWIGTYPE **O3D_PTROUT "void **"
%typemap(imtype) SWIGTYPE **O3D_PTROUT "out global::System.IntPtr"
%typemap(cstype) SWIGTYPE **O3D_PTROUT "out global::System.IntPtr"
%typemap(in) SWIGTYPE **O3D_PTROUT %{ $1 = ($1_ltype)$input; if ($1) *$1 = 0; %}
%typemap(csin) SWIGTYPE **O3D_PTROUT "out $csinput"

/* ---- errors: status -> O3d.O3dException via a registered managed callback ------------------ */
%typemap(csout, excode=SWIGEXCODE) o3d_status {
    int ret = $imcall;$excode
    return ret;
  }

%insert(runtime) %{
typedef void (SWIGSTDCALL *o3dcs_raise_callback)(int status, const char *message);
static o3dcs_raise_callback o3dcs_raise = 0;
#ifdef __cplusplus
extern "C"
#endif
SWIGEXPORT void SWIGSTDCALL O3dCsRegisterExceptionCallback(o3dcs_raise_callback callback) {
  o3dcs_raise = callback;
}
#define O3D_SWIG_RAISE(status, message) \
  do { if (o3dcs_raise) o3dcs_raise((int)(status), (message)); } while (0)
%}

%pragma(csharp) imclasscode=%{
  internal class O3dExceptionHelper {
    [global::System.Runtime.InteropServices.UnmanagedFunctionPointer(global::System.Runtime.InteropServices.CallingConvention.Cdecl)]
    public delegate void RaiseDelegate(int status,
        [global::System.Runtime.InteropServices.MarshalAs(global::System.Runtime.InteropServices.UnmanagedType.LPStr)] string message);

    // Kept in a static field: the native side holds a pointer to it for the process lifetime.
    static RaiseDelegate raiseDelegate = new RaiseDelegate(Raise);

    [global::System.Runtime.InteropServices.DllImport("$dllimport", EntryPoint="O3dCsRegisterExceptionCallback")]
    public static extern void O3dCsRegisterExceptionCallback(RaiseDelegate callback);

    [O3d.MonoPInvokeCallback(typeof(RaiseDelegate))]
    static void Raise(int status, string message) {
      SWIGPendingException.Set(new O3d.O3dException(status, message));
    }

    static O3dExceptionHelper() {
      O3dCsRegisterExceptionCallback(raiseDelegate);
    }
  }
  static O3dExceptionHelper o3dExceptionHelper = new O3dExceptionHelper();
%}
