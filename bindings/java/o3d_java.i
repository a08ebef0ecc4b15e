/* SPDX-License-Identifier: MIT */
/*
 * Java-only typemaps for bindings/swig/o3d.i (included from there; never processed alone).
 * Defines the abstract typemap names the shared interface applies, O3D_SWIG_RAISE, and a few
 * JNI helpers (direct ByteBuffer views, callback trampolines, global references).
 * The generated wrapper is compiled as C.
 */

/* The raw classes are package-private: org.o3d's hand-written classes are the API. */
%pragma(java) moduleclassmodifiers="final class"
%pragma(java) jniclassclassmodifiers="final class"
%typemap(javaclassmodifiers) SWIGTYPE "final class"
/* #define constants as Java compile-time constants. */
%javaconst(1);
/* No finalizers on the option-struct proxies: the hand-written layer deletes them in finally. */
%typemap(javafinalize) SWIGTYPE ""
/* Load libo3d_java before any native method runs (see NativeLoader.java for the search order). */
%pragma(java) jniclasscode=%{
  static {
    NativeLoader.load();
  }
%}

/* ---- arrays: one Java array per call, pinned/copied once; NULL allowed ---------------------- */
%define O3D_JAVA_ARRAY(CTYPE, JNITYPE, JTYPE, JARRAY, GET, RELEASE)
%typemap(jni) const CTYPE *O3D_IN, CTYPE *O3D_OUT "JARRAY"
%typemap(jtype) const CTYPE *O3D_IN, CTYPE *O3D_OUT "JTYPE[]"
%typemap(jstype) const CTYPE *O3D_IN, CTYPE *O3D_OUT "JTYPE[]"
%typemap(javain) const CTYPE *O3D_IN, CTYPE *O3D_OUT "$javainput"
%typemap(in) const CTYPE *O3D_IN, CTYPE *O3D_OUT %{
  $1 = $input ? ($1_ltype)(*jenv)->GET(jenv, $input, 0) : NULL;
  if ($input && !$1) return $null; /* OutOfMemoryError pending */
%}
/* input: never copied back */
%typemap(freearg) const CTYPE *O3D_IN %{ if ($1) (*jenv)->RELEASE(jenv, $input, (JNITYPE *)$1, JNI_ABORT); %}
/* output: copied back after the call (also on failure; harmless) */
%typemap(freearg) CTYPE *O3D_OUT %{ if ($1) (*jenv)->RELEASE(jenv, $input, (JNITYPE *)$1, 0); %}
%enddef
O3D_JAVA_ARRAY(double, jdouble, double, jdoubleArray, GetDoubleArrayElements, ReleaseDoubleArrayElements)
O3D_JAVA_ARRAY(float, jfloat, float, jfloatArray, GetFloatArrayElements, ReleaseFloatArrayElements)
O3D_JAVA_ARRAY(int32_t, jint, int, jintArray, GetIntArrayElements, ReleaseIntArrayElements)
O3D_JAVA_ARRAY(int64_t, jlong, long, jlongArray, GetLongArrayElements, ReleaseLongArrayElements)
O3D_JAVA_ARRAY(uint8_t, jbyte, byte, jbyteArray, GetByteArrayElements, ReleaseByteArrayElements)

/* ---- scalar outputs: T[] of length >= 1 ----------------------------------------------------- */
%define O3D_JAVA_SCALAR_OUT(CTYPE, JNITYPE, JTYPE, JARRAY, SET)
%typemap(jni) CTYPE *O3D_SOUT "JARRAY"
%typemap(jtype) CTYPE *O3D_SOUT "JTYPE[]"
%typemap(jstype) CTYPE *O3D_SOUT "JTYPE[]"
%typemap(javain) CTYPE *O3D_SOUT "$javainput"
%typemap(in) CTYPE *O3D_SOUT (CTYPE temp = 0) %{
  if (!$input || (*jenv)->GetArrayLength(jenv, $input) < 1) {
    SWIG_JavaThrowException(jenv, SWIG_JavaIllegalArgumentException, "output array of length >= 1 expected");
    return $null;
  }
  $1 = &temp;
%}
%typemap(argout) CTYPE *O3D_SOUT %{ { JNITYPE v = (JNITYPE)temp$argnum; (*jenv)->SET(jenv, $input, 0, 1, &v); } %}
%enddef
O3D_JAVA_SCALAR_OUT(size_t, jlong, long, jlongArray, SetLongArrayRegion)
O3D_JAVA_SCALAR_OUT(int32_t, jint, int, jintArray, SetIntArrayRegion)
O3D_JAVA_SCALAR_OUT(double, jdouble, double, jdoubleArray, SetDoubleArrayRegion)

/* ---- raw pointers (handles, void*, function pointers): long --------------------------------- */
%typemap(jni) SWIGTYPE *O3D_PTR "jlong"
%typemap(jtype) SWIGTYPE *O3D_PTR "long"
%typemap(jstype) SWIGTYPE *O3D_PTR "long"
%typemap(in) SWIGTYPE *O3D_PTR %{ $1 = ($1_ltype)(intptr_t)$input; %}
%typemap(out) SWIGTYPE *O3D_PTR %{ $result = (jlong)(intptr_t)$1; %}
%typemap(javain) SWIGTYPE *O3D_PTR "$javainput"
%typemap(javaout) SWIGTYPE *O3D_PTR { return $jnicall; }

/* ---- pointer outputs (`T** out`: owned handles and borrowed views): long[1] ----------------- */
%typemap(jni) SWIGTYPE **O3D_PTROUT "jlongArray"
%typemap(jtype) SWIGTYPE **O3D_PTROUT "long[]"
%typemap(jstype) SWIGTYPE **O3D_PTROUT "long[]"
%typemap(javain) SWIGTYPE **O3D_PTROUT "$javainput"
%typemap(in) SWIGTYPE **O3D_PTROUT ($*1_ltype temp = 0) %{
  if (!$input || (*jenv)->GetArrayLength(jenv, $input) < 1) {
    SWIG_JavaThrowException(jenv, SWIG_JavaIllegalArgumentException, "output array of length >= 1 expected");
    return $null;
  }
  $1 = &temp;
%}
%typemap(argout) SWIGTYPE **O3D_PTROUT %{ { jlong v = (jlong)(intptr_t)temp$argnum; (*jenv)->SetLongArrayRegion(jenv, $input, 0, 1, &v); } %}

/* ---- errors: status -> org.o3d.O3dException(status, message) -------------------------------- */
%{
static void o3dj_raise(JNIEnv *jenv, int status, const char *message) {
  jclass cls;
  jmethodID ctor;
  jstring msg;
  jobject ex;
  if ((*jenv)->ExceptionCheck(jenv)) return; /* keep the first exception */
  cls = (*jenv)->FindClass(jenv, "org/o3d/O3dException");
  if (!cls) return; /* NoClassDefFoundError pending */
  ctor = (*jenv)->GetMethodID(jenv, cls, "<init>", "(ILjava/lang/String;)V");
  if (!ctor) return;
  msg = (*jenv)->NewStringUTF(jenv, message ? message : "");
  ex = (*jenv)->NewObject(jenv, cls, ctor, (jint)status, msg);
  if (ex) (*jenv)->Throw(jenv, (jthrowable)ex);
}
#define O3D_SWIG_RAISE(status, message) o3dj_raise(jenv, (int)(status), (message))
%}

/* ---- JNI helpers (not part of the C API; used by the hand-written layer) -------------------- */
%typemap(in, numinputs=0) JNIEnv *jenv_ %{ $1 = jenv; %}
%typemap(jstype) jobject o3dj_direct_buffer "java.nio.ByteBuffer"
%typemap(javaout) jobject o3dj_direct_buffer { return (java.nio.ByteBuffer)$jnicall; }

%{
static JavaVM *o3dj_vm = 0;
static jclass o3dj_log_class = 0;
static jmethodID o3dj_log_method = 0;

static JNIEnv *o3dj_env(int *attached) {
  JNIEnv *env = 0;
  *attached = 0;
  if (!o3dj_vm) return 0;
  if ((*o3dj_vm)->GetEnv(o3dj_vm, (void **)&env, JNI_VERSION_1_6) == JNI_OK) return env;
  if ((*o3dj_vm)->AttachCurrentThread(o3dj_vm, (void **)&env, 0) != JNI_OK) return 0;
  *attached = 1;
  return env;
}

/* o3d_log_callback -> static org.o3d.Log.dispatch(int level, String message). */
static void o3dj_log_trampoline(int32_t level, const char *message, void *user_data) {
  int attached;
  JNIEnv *env = o3dj_env(&attached);
  jstring s;
  (void)user_data;
  if (!env || !o3dj_log_class) return;
  s = (*env)->NewStringUTF(env, message ? message : "");
  if (s) (*env)->CallStaticVoidMethod(env, o3dj_log_class, o3dj_log_method, (jint)level, s);
  if ((*env)->ExceptionCheck(env)) (*env)->ExceptionClear(env); /* a listener must not throw */
  if (s) (*env)->DeleteLocalRef(env, s);
  if (attached) (*o3dj_vm)->DetachCurrentThread(o3dj_vm);
}

/* o3d_progress_callback -> user_data (a global ref to an org.o3d.ProgressCallback).onProgress(fraction).
 * Returns true to go on; false (or a thrown exception, which is cleared) cancels. */
static int32_t o3dj_progress_trampoline(double fraction, void *user_data) {
  int attached;
  JNIEnv *env = o3dj_env(&attached);
  jclass cls;
  jmethodID mid;
  jboolean go_on = JNI_TRUE;
  if (!env || !user_data) return 0;
  cls = (*env)->GetObjectClass(env, (jobject)user_data);
  mid = cls ? (*env)->GetMethodID(env, cls, "onProgress", "(D)Z") : 0;
  if (mid) go_on = (*env)->CallBooleanMethod(env, (jobject)user_data, mid, (jdouble)fraction);
  if ((*env)->ExceptionCheck(env)) {
    (*env)->ExceptionClear(env);
    go_on = JNI_FALSE;
  }
  if (cls) (*env)->DeleteLocalRef(env, cls);
  if (attached) (*o3dj_vm)->DetachCurrentThread(o3dj_vm);
  return go_on ? 0 : 1;
}
%}

%inline %{
/* A direct ByteBuffer over `bytes` bytes at `address` (a borrowed o3d view); null for address 0. */
static jobject o3dj_direct_buffer(JNIEnv *jenv_, jlong address, jlong bytes) {
  if (!address || bytes <= 0) return 0;
  return (*jenv_)->NewDirectByteBuffer(jenv_, (void *)(intptr_t)address, bytes);
}
/* Address of the C log trampoline, after binding it to org.o3d.Log.dispatch(int, String). */
static jlong o3dj_log_trampoline_address(JNIEnv *jenv_) {
  if (!o3dj_vm) (*jenv_)->GetJavaVM(jenv_, &o3dj_vm);
  if (!o3dj_log_class) {
    jclass cls = (*jenv_)->FindClass(jenv_, "org/o3d/Log");
    if (!cls) return 0;
    o3dj_log_method = (*jenv_)->GetStaticMethodID(jenv_, cls, "dispatch", "(ILjava/lang/String;)V");
    if (!o3dj_log_method) return 0;
    o3dj_log_class = (jclass)(*jenv_)->NewGlobalRef(jenv_, cls);
  }
  return (jlong)(intptr_t)&o3dj_log_trampoline;
}
/* Address of the C progress trampoline; its user_data must be o3dj_new_global_ref(callback). */
static jlong o3dj_progress_trampoline_address(JNIEnv *jenv_) {
  if (!o3dj_vm) (*jenv_)->GetJavaVM(jenv_, &o3dj_vm);
  return (jlong)(intptr_t)&o3dj_progress_trampoline;
}
static jlong o3dj_new_global_ref(JNIEnv *jenv_, jobject object) {
  return object ? (jlong)(intptr_t)(*jenv_)->NewGlobalRef(jenv_, object) : 0;
}
static void o3dj_delete_global_ref(JNIEnv *jenv_, jlong ref) {
  if (ref) (*jenv_)->DeleteGlobalRef(jenv_, (jobject)(intptr_t)ref);
}
%}
