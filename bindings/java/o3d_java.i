/* SPDX-License-Identifier: MIT */
/*
 * Java-only typemaps for bindings/swig/o3d.i (included from there). Arrays are pinned or copied
 * once by JNI; results are copied once into new Java arrays. Every proxy is AutoCloseable
 * (close() == delete(), idempotent). Errors throw org.o3d.O3dException; callbacks go through
 * static C trampolines with a JNI global reference as user_data (no directors).
 */
%javaconst(1);
%pragma(java) jniclasscode=%{
  static { NativeLoader.load(); }
%}
%typemap(javainterfaces) SWIGTYPE "AutoCloseable"
%typemap(javacode) SWIGTYPE %{
  /** Frees the native object now (idempotent); later calls throw IllegalStateException. */
  @Override public void close() { delete(); }
%}

%{
static JavaVM *o3dj_vm = 0;
static JNIEnv *o3dj_env(int *attached) {
  JNIEnv *env = 0;
  *attached = 0;
  if (!o3dj_vm) return 0;
  if ((*o3dj_vm)->GetEnv(o3dj_vm, (void **)&env, JNI_VERSION_1_6) == JNI_OK) return env;
  if ((*o3dj_vm)->AttachCurrentThread(o3dj_vm, (void **)&env, 0) != JNI_OK) return 0;
  *attached = 1;
  return env;
}
static void o3dj_release(void *ref) {
  int attached;
  JNIEnv *env = ref ? o3dj_env(&attached) : 0;
  if (!env) return;
  (*env)->DeleteGlobalRef(env, (jobject)ref);
  if (attached) (*o3dj_vm)->DetachCurrentThread(o3dj_vm);
}
#define o3dx_struct_free_plain(s, _) free(s)
#define o3dx_struct_free_progress(s, _) do { o3dj_release((s)->user_data); free(s); } while (0)
%}

/* ---- arrays in / out ------------------------------------------------------------------------ */
%define O3DX_JAVA_ARRAY(E, CTYPE, JNITYPE, JTYPE, JARRAY, NAME)
%typemap(jni) o3dx_in_##E, o3dx_out_##E "JARRAY"
%typemap(jtype) o3dx_in_##E, o3dx_out_##E "JTYPE[]"
%typemap(jstype) o3dx_in_##E, o3dx_out_##E "JTYPE[]"
%typemap(javain) o3dx_in_##E "$javainput"
%typemap(javaout) o3dx_out_##E { return $jnicall; }
%typemap(in) o3dx_in_##E %{
  $1.p = $input ? (const CTYPE *)(*jenv)->Get##NAME##ArrayElements(jenv, $input, 0) : NULL;
  $1.n = $input ? (size_t)(*jenv)->GetArrayLength(jenv, $input) : 0;
  if ($input && !$1.p) return $null;
%}
%typemap(freearg) o3dx_in_##E %{ if ($1.p) (*jenv)->Release##NAME##ArrayElements(jenv, $input, (JNITYPE *)$1.p, JNI_ABORT); %}
%typemap(out) o3dx_out_##E %{
  $result = 0;
  if ($1.p) {
    $result = (*jenv)->New##NAME##Array(jenv, (jsize)$1.n);
    if ($result) (*jenv)->Set##NAME##ArrayRegion(jenv, $result, 0, (jsize)$1.n, (const JNITYPE *)$1.p);
    if ($1.owned) free($1.p);
  }
%}
%enddef
O3DX_JAVA_ARRAY(f64, double, jdouble, double, jdoubleArray, Double)
O3DX_JAVA_ARRAY(f32, float, jfloat, float, jfloatArray, Float)
O3DX_JAVA_ARRAY(i32, int32_t, jint, int, jintArray, Int)
O3DX_JAVA_ARRAY(i64, int64_t, jlong, long, jlongArray, Long)
O3DX_JAVA_ARRAY(u8, uint8_t, jbyte, byte, jbyteArray, Byte)

/* views (*View methods): a direct ByteBuffer over the borrowed memory, native order, read-only unless
   the method is a *MutableView; valid until its owner changes or is closed */
%typemap(jni) o3dx_view, o3dx_mview "jobject"
%typemap(jtype) o3dx_view, o3dx_mview "java.nio.ByteBuffer"
%typemap(jstype) o3dx_view, o3dx_mview "java.nio.ByteBuffer"
%typemap(out) o3dx_view, o3dx_mview %{ $result = (*jenv)->NewDirectByteBuffer(jenv, $1.p ? $1.p : (void *)&o3dx_view_null, (jlong)$1.bytes); %}
%typemap(javaout) o3dx_mview { return $jnicall.order(java.nio.ByteOrder.nativeOrder()); }
%typemap(javaout) o3dx_view { return $jnicall.asReadOnlyBuffer().order(java.nio.ByteOrder.nativeOrder()); }

/* text results (o3dx_text): a String; the native copy is freed */
%typemap(jni) o3dx_text "jstring"
%typemap(jtype) o3dx_text "String"
%typemap(jstype) o3dx_text "String"
%typemap(javaout) o3dx_text { return $jnicall; }
%typemap(out) o3dx_text %{ $result = $1 ? (*jenv)->NewStringUTF(jenv, $1) : 0; free($1); %}

/* correspondence checkers: CorrespondenceChecker[] -> one contiguous C array */
%typemap(jni) o3dx_in_o3d_correspondence_checker_t "jlongArray"
%typemap(jtype) o3dx_in_o3d_correspondence_checker_t "long[]"
%typemap(jstype) o3dx_in_o3d_correspondence_checker_t "CorrespondenceChecker[]"
%typemap(javain) o3dx_in_o3d_correspondence_checker_t
  "$javainput == null ? null : java.util.Arrays.stream($javainput).mapToLong(CorrespondenceChecker::getCPtr).toArray()"
%typemap(in) o3dx_in_o3d_correspondence_checker_t (o3d_correspondence_checker_t *tmp = NULL) %{
  $1.n = $input ? (size_t)(*jenv)->GetArrayLength(jenv, $input) : 0;
  if ($1.n) {
    size_t i;
    jlong *ptrs = (*jenv)->GetLongArrayElements(jenv, $input, 0);
    tmp = (o3d_correspondence_checker_t *)malloc($1.n * sizeof *tmp);
    for (i = 0; tmp && ptrs && i < $1.n; ++i) tmp[i] = *(o3d_correspondence_checker_t *)(intptr_t)ptrs[i];
    if (ptrs) (*jenv)->ReleaseLongArrayElements(jenv, $input, ptrs, JNI_ABORT);
  }
  $1.p = tmp;
%}
%typemap(freearg) o3dx_in_o3d_correspondence_checker_t %{ free(tmp$argnum); %}

/* arrays of handles: RGBDImage[] etc. -> a C array of their handles (a null element is a NULL handle) */
%define O3DX_HANDLES_IN(T, CLS)
%typemap(jni) o3dx_handles_##T "jlongArray"
%typemap(jtype) o3dx_handles_##T "long[]"
%typemap(jstype) o3dx_handles_##T "CLS[]"
%typemap(javain) o3dx_handles_##T
  "$javainput == null ? null : java.util.Arrays.stream($javainput).mapToLong(CLS::getCPtr).toArray()"
%typemap(in) o3dx_handles_##T (const T **tmp = NULL) %{
  $1.n = $input ? (size_t)(*jenv)->GetArrayLength(jenv, $input) : 0;
  if ($1.n) {
    size_t i;
    jlong *ptrs = (*jenv)->GetLongArrayElements(jenv, $input, 0);
    tmp = (const T **)malloc($1.n * sizeof *tmp);
    for (i = 0; tmp && ptrs && i < $1.n; ++i) tmp[i] = (const T *)(intptr_t)ptrs[i];
    if (ptrs) (*jenv)->ReleaseLongArrayElements(jenv, $input, ptrs, JNI_ABORT);
  }
  $1.p = tmp;
%}
%typemap(freearg) o3dx_handles_##T %{ free((void *)tmp$argnum); %}
%enddef

/* ---- errors: O3dException(status, message); a closed object: IllegalStateException ---------- */
%{
static O3DX_TLS jthrowable o3dj_thrown; /* what a Visualizer callback threw: the failed call throws it */
static void o3dj_raise(JNIEnv *jenv, int status, const char *message) {
  jclass cls;
  jmethodID ctor;
  jobject ex;
  if ((*jenv)->ExceptionCheck(jenv)) return; /* keep the first exception */
  if (o3dj_thrown) {
    (*jenv)->Throw(jenv, o3dj_thrown);
    (*jenv)->DeleteGlobalRef(jenv, o3dj_thrown);
    o3dj_thrown = 0;
    return;
  }
  if (status == O3DX_DISPOSED) {
    cls = (*jenv)->FindClass(jenv, "java/lang/IllegalStateException");
    if (cls) (*jenv)->ThrowNew(jenv, cls, message);
    return;
  }
  cls = (*jenv)->FindClass(jenv, "org/o3d/O3dException");
  ctor = cls ? (*jenv)->GetMethodID(jenv, cls, "<init>", "(ILjava/lang/String;)V") : 0;
  ex = ctor ? (*jenv)->NewObject(jenv, cls, ctor, (jint)status, (*jenv)->NewStringUTF(jenv, message ? message : "")) : 0;
  if (ex) (*jenv)->Throw(jenv, (jthrowable)ex);
}
#define O3D_SWIG_RAISE(status, message) o3dj_raise(jenv, (int)(status), (message))
%}

/* ---- callbacks ------------------------------------------------------------------------------ */
%typemap(in, numinputs=0) JNIEnv *jenv_ %{ $1 = jenv; %}
%typemap(jni) jobject progress "jobject"
%typemap(jtype) jobject progress "Object"
%typemap(jstype) jobject progress "ProgressCallback"
%typemap(javain) jobject progress "$javainput"
%typemap(jni) jobject handler "jobject"
%typemap(jtype) jobject handler "Object"
%typemap(jstype) jobject handler "java.util.function.BiConsumer<Integer, String>"
%typemap(javain) jobject handler "$javainput"
%{
/* o3d_progress_callback -> ((ProgressCallback)user_data).onProgress(fraction); false or a throw cancels. */
static int32_t o3dj_progress(double fraction, void *user_data) {
  int attached;
  JNIEnv *env = o3dj_env(&attached);
  jclass cls;
  jmethodID mid;
  jboolean go_on = JNI_TRUE;
  if (!env || !user_data) return 0;
  cls = (*env)->GetObjectClass(env, (jobject)user_data);
  mid = cls ? (*env)->GetMethodID(env, cls, "onProgress", "(D)Z") : 0;
  if (mid) go_on = (*env)->CallBooleanMethod(env, (jobject)user_data, mid, (jdouble)fraction);
  if ((*env)->ExceptionCheck(env)) { (*env)->ExceptionClear(env); go_on = JNI_FALSE; }
  if (cls) (*env)->DeleteLocalRef(env, cls);
  if (attached) (*o3dj_vm)->DetachCurrentThread(o3dj_vm);
  return go_on ? 0 : 1;
}
static void o3dj_set_progress(JNIEnv *jenv, o3d_progress_callback *fn, void **user_data, jobject progress) {
  if (!o3dj_vm) (*jenv)->GetJavaVM(jenv, &o3dj_vm);
  if (*user_data) (*jenv)->DeleteGlobalRef(jenv, (jobject)*user_data);
  *user_data = progress ? (void *)(*jenv)->NewGlobalRef(jenv, progress) : NULL;
  *fn = progress ? o3dj_progress : NULL;
}
/* o3d_log_callback -> the handler (a global reference) .accept(level, message) */
static jobject o3dj_log_handler = 0;
static void o3dj_log(int32_t level, const char *message, void *user_data) {
  int attached;
  JNIEnv *env = o3dj_env(&attached);
  jclass icls;
  jmethodID accept, valueOf;
  (void)user_data;
  if (!env || !o3dj_log_handler) return;
  icls = (*env)->FindClass(env, "java/lang/Integer");
  valueOf = icls ? (*env)->GetStaticMethodID(env, icls, "valueOf", "(I)Ljava/lang/Integer;") : 0;
  accept = (*env)->GetMethodID(env, (*env)->GetObjectClass(env, o3dj_log_handler), "accept", "(Ljava/lang/Object;Ljava/lang/Object;)V");
  if (valueOf && accept)
    (*env)->CallVoidMethod(env, o3dj_log_handler, accept, (*env)->CallStaticObjectMethod(env, icls, valueOf, (jint)level),
                           (*env)->NewStringUTF(env, message ? message : ""));
  if ((*env)->ExceptionCheck(env)) (*env)->ExceptionClear(env); /* a handler must not throw */
  if (attached) (*o3dj_vm)->DetachCurrentThread(o3dj_vm);
}
%}
%define O3DX_PROGRESS(T)
%extend T { void set_progress(JNIEnv *jenv_, jobject progress) { o3dj_set_progress(jenv_, &$self->progress, &$self->user_data, progress); } }
%enddef
%inline %{
/* Send o3d's log lines to handler (level, message); null restores stderr. */
static void set_log_handler(JNIEnv *jenv_, jobject handler) {
  if (!o3dj_vm) (*jenv_)->GetJavaVM(jenv_, &o3dj_vm);
  o3d_set_log_callback(NULL, NULL);
  if (o3dj_log_handler) (*jenv_)->DeleteGlobalRef(jenv_, o3dj_log_handler);
  o3dj_log_handler = handler ? (*jenv_)->NewGlobalRef(jenv_, handler) : 0;
  if (handler) o3d_set_log_callback(o3dj_log, NULL);
}
%}

/* ---- Visualizer callbacks: user_data a WEAK global reference to an IntBinaryOperator (action, mods) ->
   changed, kept by the proxy (a callback capturing the visualizer makes no GC root). A throw is kept
   (o3dj_thrown), stops the loop (o3d_visualizer_set_callback_error) and comes out of the call that ran it. */
%{
static int32_t o3dj_visualizer_key(o3d_visualizer_t *vis, int32_t action, int32_t mods, void *user_data) {
  int attached;
  JNIEnv *env = o3dj_env(&attached);
  int framed = env && !o3dj_thrown && (*env)->PushLocalFrame(env, 4) == 0; /* frees the local references */
  jobject fn = framed ? (*env)->NewLocalRef(env, (jobject)user_data) : 0;
  jint changed = fn ? (*env)->CallIntMethod(env, fn, (*env)->GetMethodID(env, (*env)->GetObjectClass(env, fn), "applyAsInt", "(II)I"), action, mods) : 0;
  jthrowable ex = fn ? (*env)->ExceptionOccurred(env) : 0;
  if (ex) {
    (*env)->ExceptionClear(env);
    o3dj_thrown = (jthrowable)(*env)->NewGlobalRef(env, ex);
    o3d_visualizer_set_callback_error(vis, "a Java callback threw");
  }
  if (framed) (*env)->PopLocalFrame(env, 0);
  if (attached) (*o3dj_vm)->DetachCurrentThread(o3dj_vm);
  return changed;
}
static int32_t o3dj_visualizer_animation(o3d_visualizer_t *vis, void *user_data) { return o3dj_visualizer_key(vis, 0, 0, user_data); }
%}
%rename(closeWindow) o3d_visualizer_t::close; /* close() is AutoCloseable's: it frees */
%javamethodmodifiers o3d_visualizer_t::register_native "private";
%javamethodmodifiers o3d_visualizer_t::release_ref "private";
%extend o3d_visualizer_t {
  /* kind 0: animation, 1: key, 2: key action; returns the weak reference native code holds */
  int64_t register_native(JNIEnv *jenv_, int32_t kind, int32_t key, jobject callback) {
    jweak ref = callback ? (*jenv_)->NewWeakGlobalRef(jenv_, callback) : 0;
    void (*fn)(void) = !callback ? NULL : kind ? (void (*)(void))o3dj_visualizer_key : (void (*)(void))o3dj_visualizer_animation;
    if (!o3dj_vm) (*jenv_)->GetJavaVM(jenv_, &o3dj_vm);
    if ((o3dx_err = o3dx_visualizer_register($self, kind, key, fn, ref)) != O3D_OK && ref) (*jenv_)->DeleteWeakGlobalRef(jenv_, ref);
    return o3dx_err ? 0 : (int64_t)(intptr_t)ref;
  }
  static void release_ref(JNIEnv *jenv_, int64_t ref) { if (ref) (*jenv_)->DeleteWeakGlobalRef(jenv_, (jweak)(intptr_t)ref); }
  void play_view_trajectory(JNIEnv *jenv_, const char *trajectory_path, const char *capture_dir, int32_t capture_depth, jobject progress) {
    if (!o3dj_vm) (*jenv_)->GetJavaVM(jenv_, &o3dj_vm);
    o3dx_err = o3d_visualizer_play_view_trajectory($self, trajectory_path, capture_dir, capture_depth, progress ? o3dj_progress : NULL, progress);
  }
}
%typemap(javadestruct, methodname="delete", methodmodifiers="public synchronized") o3d_visualizer_t {
    if (swigCPtr != 0 && swigCMemOwn) $jnicall;
    swigCPtr = 0;
    swigCMemOwn = false;
    callbacks.values().forEach(c -> releaseRef(c.getValue()));
    callbacks.clear();
  }
%typemap(javaimports) o3d_visualizer_t "import java.util.*;\nimport java.util.function.*;"
%typemap(javacode) o3d_visualizer_t %{
  /** Frees the native viewer now (idempotent) and releases its callbacks; later calls throw IllegalStateException. */
  @Override public void close() { delete(); }
  /** A key action callback: action O3D_KEY_ACTION_*, mods O3D_KEY_MOD_* bits; true when the geometry or view changed. */
  @FunctionalInterface public interface KeyActionCallback { boolean onKey(Visualizer vis, int action, int mods); }
  /** Called once per loop of run(); true when the geometry or the view changed; null removes it. */
  public void registerAnimationCallback(Predicate<Visualizer> f) { register(0, -1, f == null ? null : (a, m) -> f.test(this) ? 1 : 0); }
  /** Called on press and repeat of {@code key} ('A' = 65, Library.KEY_*) instead of o3d's binding; null removes it. */
  public void registerKeyCallback(int key, Predicate<Visualizer> f) { register(1, key, f == null ? null : (a, m) -> f.test(this) ? 1 : 0); }
  /** As registerKeyCallback, also on release. */
  public void registerKeyActionCallback(int key, KeyActionCallback f) { register(2, key, f == null ? null : (a, m) -> f.onKey(this, a, m) ? 1 : 0); }
  private final Map<Integer, Map.Entry<IntBinaryOperator, Long>> callbacks = new HashMap<>(); // by key, -1: animation
  private synchronized void register(int kind, int key, IntBinaryOperator fn) {
    long ref = registerNative(kind, key, fn);
    Map.Entry<IntBinaryOperator, Long> old = fn == null ? callbacks.remove(kind == 0 ? -1 : key) : callbacks.put(kind == 0 ? -1 : key, Map.entry(fn, ref));
    if (old != null) releaseRef(old.getValue());
  }
%}
