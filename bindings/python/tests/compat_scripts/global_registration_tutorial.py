# Open3D's global-registration tutorial (RANSAC and FGR on FPFH features, then point-to-plane refinement),
# written with Open3D 0.20's API only. test_open3d_compat_registration.py runs it with o3d bound to the name
# `open3d`; tools/reference/record_python_registration.py runs it with the real Open3D and prints `result`,
# recorded in the test. Inputs: `open3d`, `np`, `result` (a dict to fill), `DATA` (the open3d test-data dir).
import os

open3d.utility.random.seed(42)
voxel_size = 0.05  # 5 cm for this dataset


def preprocess_point_cloud(pcd, voxel_size):
    pcd_down = pcd.voxel_down_sample(voxel_size)
    radius_normal = voxel_size * 2
    pcd_down.estimate_normals(open3d.geometry.KDTreeSearchParamHybrid(radius=radius_normal, max_nn=30))
    radius_feature = voxel_size * 5
    pcd_fpfh = open3d.pipelines.registration.compute_fpfh_feature(
        pcd_down, open3d.geometry.KDTreeSearchParamHybrid(radius=radius_feature, max_nn=100))
    return pcd_down, pcd_fpfh


source = open3d.io.read_point_cloud(os.path.join(DATA, "Feature", "cloud_bin_0.pcd"))
target = open3d.io.read_point_cloud(os.path.join(DATA, "Feature", "cloud_bin_1.pcd"))
trans_init = np.asarray([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
source.transform(trans_init)
source_down, source_fpfh = preprocess_point_cloud(source, voxel_size)
target_down, target_fpfh = preprocess_point_cloud(target, voxel_size)
result["down"] = (len(source_down.points), len(target_down.points))
result["fpfh"] = (source_fpfh.dimension(), source_fpfh.num(), target_fpfh.dimension(), target_fpfh.num())

# The two scans are aligned to about 0.4 deg / 17 mm, so the answer is the inverse of trans_init.
truth = np.linalg.inv(trans_init)


def recovered(transformation, degrees=5.0, metres=0.25):
    delta = np.linalg.inv(truth) @ np.asarray(transformation)
    angle = np.degrees(np.arccos(np.clip((np.trace(delta[:3, :3]) - 1.0) / 2.0, -1.0, 1.0)))
    return bool(angle < degrees and np.linalg.norm(delta[:3, 3]) < metres)


distance_threshold = voxel_size * 1.5
ransac = open3d.pipelines.registration.registration_ransac_based_on_feature_matching(
    source_down, target_down, source_fpfh, target_fpfh, True, distance_threshold,
    open3d.pipelines.registration.TransformationEstimationPointToPoint(False), 3, [
        open3d.pipelines.registration.CorrespondenceCheckerBasedOnEdgeLength(0.9),
        open3d.pipelines.registration.CorrespondenceCheckerBasedOnDistance(distance_threshold)
    ], open3d.pipelines.registration.RANSACConvergenceCriteria(100000, 0.999))
result["ransac"] = recovered(ransac.transformation)

fgr = open3d.pipelines.registration.registration_fgr_based_on_feature_matching(
    source_down, target_down, source_fpfh, target_fpfh,
    open3d.pipelines.registration.FastGlobalRegistrationOption(maximum_correspondence_distance=voxel_size * 0.5))
result["fgr"] = recovered(fgr.transformation)

refined = open3d.pipelines.registration.registration_icp(
    source, target, voxel_size * 0.4, ransac.transformation,
    open3d.pipelines.registration.TransformationEstimationPointToPlane())
result["icp"] = (recovered(refined.transformation, 0.6, 0.025), round(refined.fitness, 2))
