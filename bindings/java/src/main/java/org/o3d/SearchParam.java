// SPDX-License-Identifier: MIT
package org.o3d;

/** Neighbourhood search parameter (KDTreeSearchParamKNN / Radius / Hybrid). Immutable. */
public final class SearchParam {
    public enum Kind {
        KNN(O3dNativeConstants.O3D_SEARCH_KNN),
        RADIUS(O3dNativeConstants.O3D_SEARCH_RADIUS),
        HYBRID(O3dNativeConstants.O3D_SEARCH_HYBRID);

        final int code;

        Kind(int code) {
            this.code = code;
        }
    }

    private final Kind kind;
    private final int maxNN;
    private final double radius;

    private SearchParam(Kind kind, int maxNN, double radius) {
        this.kind = kind;
        this.maxNN = maxNN;
        this.radius = radius;
    }

    public static SearchParam knn(int knn) { return new SearchParam(Kind.KNN, knn, 0.0); }
    public static SearchParam radius(double radius) { return new SearchParam(Kind.RADIUS, 0, radius); }
    public static SearchParam hybrid(double radius, int maxNN) { return new SearchParam(Kind.HYBRID, maxNN, radius); }

    public Kind kind() { return kind; }
    public int maxNN() { return maxNN; }
    public double radius() { return radius; }

    /** A native o3d_search_param_t filled by o3d_search_param_init; the caller must delete() it. */
    o3d_search_param_t toNative() {
        o3d_search_param_t p = new o3d_search_param_t();
        O3dNative.o3d_search_param_init(p, O3dNative.o3dx_sizeof_search_param());
        p.setKind(kind.code);
        p.setKnn(maxNN);
        p.setRadius(radius);
        return p;
    }
}
