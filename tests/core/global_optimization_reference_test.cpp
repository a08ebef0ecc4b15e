// SPDX-License-Identifier: MIT
// Global optimization against Open3D's own numbers: Open3D's test_pose_graph.json and a well-formed ring
// with a false loop closure, both methods, default options and a fixed reference node.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "o3d/io/pose_graph_io.h"
#include "o3d/registration/global_optimization.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace reg = o3d::registration;

namespace {

// Numbers printed by tools/reference/record_pose_graph.py with Open3D 0.20.0 (PyPI wheel), numpy 2.4.6.
// Poses are row-major, one node after another; confidences and ids are those of the edges left, in order.
// Open3D 0.20.0, numpy 2.4.6
// test_pose_graph.json: 2 nodes, 2 edges
constexpr double kFileNode0[] = {
    -0.9974974822229682, 0.1700186162907804, 0.6456801049836727, 0.4210028382213813,
    0.12717062898648024, -0.04025391399884026, 0.4932096316415906, 0.027069917905209406,
    -0.6133915219580676, -0.2994170964690085, -0.651783806878872, -0.3920102542191839,
    0.6174810022278512, 0.7919248023926511, 0.717886898403882, -0.9700308236945707,
};
constexpr double kFileEdge0Transformation[] = {
    0.17581713309121993, -0.03012176885280926, -0.08407849360637232, 0.1980956450086977,
    0.38236640522476883, -0.5892818994720298, 0.8983123264259774, -0.2295297097689749,
    0.6752220221564378, 0.48747215186010306, 0.4888760032959991, 0.4700155644398327,
    0.45298623615222633, -0.06308175908688618, -0.7834406567583239, 0.21793267616809597,
};
constexpr double kFileEdge0Information[] = {
    -0.09842219306009092, 0.03976561784722432, 0.07870723593859674, 0.5593127231666006,
    -0.467574083681753, 0.3544114505447553, -0.2957548753318888, -0.3960997344889675,
    -0.7153233436078982, 0.6873073519089328, -0.4054383983886227, -0.8875698110904263,
    -0.8859218115787225, 0.7519455549790948, -0.07583849604785298, 0.9935911130100405,
    0.6802880947294534, -0.9824213385418257, 0.21536912137211228, 0.4533524582659383,
    -0.5293435468611714, 0.9993896298104801, -0.9525131992553484, 0.8375804925687429,
    0.56663716544084, 0.9118015076143682, 0.7244788964506974, 0.22299874874111159,
    -0.2482680745872372, -0.4482253486739708, 0.6052125614185002, 0.8514358958708457,
    -0.5807977538377025, -0.2151249732963042, -0.814752647480697, -0.4542069765312662,
};
// [1;33m[Open3D WARNING] Invalid PoseGraph - graph is not connected.[0;m
// after global_optimization: 2 edges, poses unchanged: True
// ring(8) as built: node 7 pose and the false closure's measurement
constexpr double kRingNode7[] = {
    0.6972867901773128, 0.7161201692292364, 0.031032812752161798, -0.6860383247836248,
    -0.7162616881243383, 0.6944518930869498, 0.0685985591191634, -1.463968912857744,
    0.027574016201745443, -0.07006048394809977, 0.9971615727751769, -0.16247041104127258,
    0.0, 0.0, 0.0, 1.0,
};
constexpr double kRingFalseClosure[] = {
    -0.9983936085407528, 0.02177079286571915, -0.052309033665058874, -2.771791684602565,
    -0.023889126219670483, -0.9989052918684567, 0.04021849730726017, -1.8980211045663298,
    -0.051376181966305695, 0.0414035077643356, 0.9978207441576736, -0.02490100419080471,
    0.0, 0.0, 0.0, 1.0,
};
// RingLM: 8 nodes, 10 edges left
constexpr size_t kRingLMEdges = 10;
constexpr int kRingLMEdgeIds[] = {
    0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 0, 3, 0, 6, 3,
};
constexpr double kRingLMConfidence[] = {
    1.0, 1.0, 1.0, 1.0,
    1.0, 1.0, 1.0, 0.9585480190692097,
    0.9508389482140293, 0.9807932426119601,
};
constexpr double kRingLMPoses[] = {
    0.9998975574482452, 0.0112785520518836, -0.008812994533414, -0.031190342365800646,
    -0.011207265489439162, 0.9999044153576339, 0.008096749258669704, -0.0441602967062352,
    0.008903471754448302, -0.00799715023752178, 0.9999283843249956, 0.028247839582208237,
    0.0, 0.0, 0.0, 1.0,
    0.7194628723091969, -0.6937098769299301, 0.03376065784994953, -0.6023780723466232,
    0.694497750442387, 0.7181031269525654, -0.044730008846540804, 1.3750123563315833,
    0.006786014961984065, 0.0556282815733931, 0.9984284873190101, 0.19717649252541566,
    0.0, 0.0, 0.0, 1.0,
    0.024962297995456805, -0.9922642899233829, -0.12160782302808797, -1.9972334868228272,
    0.9996690759033481, 0.024020212738488995, 0.009206957290228461, 1.982811490023967,
    -0.006214689158144207, -0.12179740688061673, 0.9925355254678923, -0.026398720911303256,
    0.0, 0.0, 0.0, 1.0,
    -0.6912042046643155, -0.7218396202537296, 0.03441380662354186, -3.4270873111748203,
    0.722569060781388, -0.6895802541737217, 0.048713709109531426, 1.4169878313461617,
    -0.011432403766227438, 0.058537472491187355, 0.9982197475798951, -0.2455197567989108,
    0.0, 0.0, 0.0, 1.0,
    -0.9997933093279215, -0.019091189476038002, -0.006990358182075035, -4.040011825857713,
    0.019065195264139308, -0.9998111479549007, 0.003766530850003428, 0.008782859698260181,
    -0.007060945592761133, 0.0036324797995029843, 0.9999684735719635, -0.06106314373685468,
    0.0, 0.0, 0.0, 1.0,
    -0.7189258880781997, 0.694449819131153, 0.029749221160917043, -3.4843994859769087,
    -0.6949769457224677, -0.7173930167520428, -0.04852117506485234, -1.4097103734952927,
    -0.012353637733163812, -0.05555815173413317, 0.9983790259268496, 0.14853676944777572,
    0.0, 0.0, 0.0, 1.0,
    -0.014795005156930158, 0.9926698466110934, -0.11994867006980378, -2.070559712496783,
    -0.9998882903283686, -0.014943050224644462, -0.00033483458060593844, -2.0183210065022585,
    -0.0021247791930026974, 0.11993031676391085, 0.9927800382936239, -0.01235021419984193,
    0.0, 0.0, 0.0, 1.0,
    0.7009892202274581, 0.712307258471259, 0.03510673231817282, -0.6424871590256122,
    -0.7129694107772243, 0.6987677532554851, 0.058294479209093496, -1.4425265954226978,
    0.016992128203327836, -0.06589382777954943, 0.9976819488392488, -0.18086184814133227,
    0.0, 0.0, 0.0, 1.0,
};
// RingGN: 8 nodes, 10 edges left
constexpr size_t kRingGNEdges = 10;
constexpr int kRingGNEdgeIds[] = {
    0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 0, 3, 0, 6, 3,
};
constexpr double kRingGNConfidence[] = {
    1.0, 1.0, 1.0, 1.0,
    1.0, 1.0, 1.0, 0.9585482835310383,
    0.9508388162084022, 0.9807932111751421,
};
constexpr double kRingGNPoses[] = {
    0.9997704503044198, -0.006505045591336936, -0.020413992259051827, -0.07511492690176734,
    0.006821980521297136, 0.9998566828151005, 0.015494334827614243, -0.004175066423822788,
    0.02031027522868763, -0.015630041965324505, 0.9996715433122507, 0.00270624989212382,
    0.0, 0.0, 0.0, 1.0,
    0.7068091921390689, -0.7070266080989708, 0.023111498172582342, -0.6734765238162285,
    0.7073399107569228, 0.705927018386141, -0.03656904924716465, 1.4057453725642377,
    0.009540259855219236, 0.04219502521053548, 0.9990638434501459, 0.15413639811266713,
    0.0, 0.0, 0.0, 1.0,
    0.0071593992641443595, -0.9910742661577432, -0.1331185259911898, -2.076319577018747,
    0.9998806429530852, 0.005272397050354159, 0.014522454237111942, 1.986685399433214,
    -0.013690976952071634, -0.13320660940521656, 0.9909937216556237, -0.08992781654821537,
    0.0, 0.0, 0.0, 1.0,
    -0.7038328732042998, -0.7100218487221363, 0.022096627212770063, -3.4932263853158165,
    0.7099302688403025, -0.7019723286383452, 0.05686706613141722, 1.3936305285565356,
    -0.024865638566431147, 0.055711975043599996, 0.9981372029212342, -0.32082480492198173,
    0.0, 0.0, 0.0, 1.0,
    -0.9998277948991631, -0.0012574850814338324, -0.018514839409161248, -4.082955613560013,
    0.0010502581223365644, -0.9999367494145799, 0.011197951959179496, -0.023922066324398004,
    -0.018527749592260945, 0.011176578254259857, 0.9997658758897368, -0.1323944341969583,
    0.0, 0.0, 0.0, 1.0,
    -0.706199962235007, 0.7077528890492872, 0.019169282241700523, -3.504515629660155,
    -0.7078514508383956, -0.7052032205181311, -0.040431934369200215, -1.4305820718843216,
    -0.015097578787784482, -0.042122034770935964, 0.9989983970465133, 0.09448669447713379,
    0.0, 0.0, 0.0, 1.0,
    0.003105080303639261, 0.9913388758266861, -0.13129200947121783, -2.078272406529565,
    -0.9999802235259103, 0.0037962114149000196, 0.005014113676834088, -2.0148981900641108,
    0.005469098040699594, 0.13127384375257622, 0.991331058180387, -0.0456538138817417,
    0.0, 0.0, 0.0, 1.0,
    0.713380369971751, 0.7004117282052156, 0.022624295161426635, -0.6588827563666109,
    -0.7001146820543648, 0.7109312523536474, 0.06645439337463782, -1.4148361605316275,
    0.030461118017627666, -0.06324686094549353, 0.9975329342280675, -0.2024505095903462,
    0.0, 0.0, 0.0, 1.0,
};
// RingLMRef0: 8 nodes, 10 edges left
constexpr size_t kRingLMRef0Edges = 10;
constexpr int kRingLMRef0EdgeIds[] = {
    0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 0, 3, 0, 6, 3,
};
constexpr double kRingLMRef0Confidence[] = {
    1.0, 1.0, 1.0, 1.0,
    1.0, 1.0, 1.0, 0.9585480190692097,
    0.9508389482140293, 0.9807932426119601,
};
constexpr double kRingLMRef0Poses[] = {
    1.0, 1.328147661294743e-18, -1.734723475976807e-18, -3.469446951953614e-18,
    -3.9302328752599536e-19, 0.9999999999999999, 0.0, -6.938893903907228e-18,
    0.0, -1.734723475976807e-18, 1.0, 0.0,
    0.0, 0.0, 0.0, 1.0,
    0.711666167118178, -0.7011914990787768, 0.04314798024217996, -0.5855302092601822,
    0.7024915977968587, 0.7097655766409359, -0.05232954462228741, 1.4112438835663266,
    0.00606808076232886, 0.06755226003041924, 0.9976972840299027, 0.18544111447198172,
    0.0, 0.0, 0.0, 1.0,
    0.013700851749339148, -0.9935162605107078, -0.11286153801079529, -1.989045093041769,
    0.9999047612723967, 0.013800644493283491, -0.00010293862867430739, 2.005040936170104,
    0.001659833164474843, -0.11284937887462905, 0.9936107198704512, -0.020904037147087075,
    0.0, 0.0, 0.0, 1.0,
    -0.699333207324456, -0.7135161774433713, 0.04275195504172004, -3.4143620415101816,
    0.7147956383258355, -0.698123779583924, 0.041114277444917434, 1.4248970246040116,
    0.0005104543574839509, 0.05931149050610526, 0.9982393933973418, -0.23198941888514396,
    0.0, 0.0, 0.0, 1.0,
    -0.9999674235846648, -0.007851743070147058, 0.0018713364766314265, -4.009799335416632,
    0.007843619486612696, -0.9999599518248187, -0.004309568407058994, 0.008438627435015299,
    0.0019050991568958378, -0.004294749965514647, 0.9999889627990584, -0.05354619797089067,
    0.0, 0.0, 0.0, 1.0,
    -0.7111734386005731, 0.7019240314839312, 0.039179002723173276, -3.436480316715564,
    -0.7029201657528625, -0.7090477496782717, -0.05616519611064784, -1.4053287188896384,
    -0.011643917167566738, -0.06748290673588986, 0.997652482827297, 0.13965691202612138,
    0.0, 0.0, 0.0, 1.0,
    -0.0036063939008865492, 0.9938034218978558, -0.11109344061259498, -2.0173969723603666,
    -0.9999425904210736, -0.004704844124388924, -0.00962706101354553, -1.9966484752091973,
    -0.010090083499405432, 0.11105234381082518, 0.9937633355830239, -0.03860647947798421,
    0.0, 0.0, 0.0, 1.0,
    0.7090591355089211, 0.703816328337447, 0.043332647241278666, -0.5974241336910617,
    -0.7051310070450296, 0.7072617191217742, 0.05070624782583742, -1.4034548977509047,
    0.005040362586585401, -0.06650892143545904, 0.9977730995143577, -0.21502957798106917,
    0.0, 0.0, 0.0, 1.0,
};
// RingGNRef3: 8 nodes, 10 edges left
constexpr size_t kRingGNRef3Edges = 10;
constexpr int kRingGNRef3EdgeIds[] = {
    0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 0, 3, 0, 6, 3,
};
constexpr double kRingGNRef3Confidence[] = {
    1.0, 1.0, 1.0, 1.0,
    1.0, 1.0, 1.0, 0.9585482835310383,
    0.9508388162084022, 0.9807932111751421,
};
constexpr double kRingGNRef3Poses[] = {
    0.9998182501299225, 0.011616185737247403, -0.015117239697029189, -0.02806356983865857,
    -0.011499421048731308, 0.999903549884523, 0.007788083453153185, -0.04036734583427002,
    0.015206249461443718, -0.007612828465626704, 0.9998553969550144, 0.048187676161089765,
    0.0, 0.0, 0.0, 1.0,
    0.7196053635502667, -0.693840491050465, 0.027449840227910426, -0.5998974423042184,
    0.6942873505893087, 0.718286519237025, -0.045050539331261255, 1.3789179120166841,
    0.01154103814077233, 0.051476686579543636, 0.9986075080718275, 0.21395472317706798,
    0.0, 0.0, 0.0, 1.0,
    0.025288351480078988, -0.9914694065514833, -0.12786287636319213, -1.9931402085526586,
    0.9996636954519879, 0.024345299919545687, 0.008933217063492198, 1.9871902757015605,
    -0.00574415134689845, -0.12804578182929868, 0.9917516233820984, -0.01822325486721499,
    0.0, 0.0, 0.0, 1.0,
    -0.6909106202669099, -0.7223926590436147, 0.028131138659672598, -3.4217461358316092,
    0.7227725999466843, -0.6893895002418255, 0.04839303382344138, 1.4218486966161448,
    -0.015565460761078159, 0.05376767724406359, 0.9984321475769267, -0.2465353351649414,
    0.0, 0.0, 0.0, 1.0,
    -0.999723366301273, -0.019401114369865184, -0.013296151039216475, -4.036226626772528,
    0.019356749383670022, -0.9998066629809239, 0.0034572984029660313, 0.013763834410480097,
    -0.013360655842736062, 0.0031989717342875805, 0.999905625274353, -0.06638907905342874,
    0.0, 0.0, 0.0, 1.0,
    -0.7190334102181077, 0.6945801823135032, 0.023437690318343953, -3.482355094568125,
    -0.6947649693036375, -0.7175766432504099, -0.048840541458818616, -1.4049553096506642,
    -0.017105333046576642, -0.0514016672766057, 0.9985315599331607, 0.14626686102890857,
    0.0, 0.0, 0.0, 1.0,
    -0.01506872790822664, 0.9918893386095452, -0.12620805597087179, -2.0677036985411203,
    -0.9998832566635548, -0.01526767803914186, -0.0006091397027048126, -2.013924994597177,
    -0.0025311031413460623, 0.12618414306089337, 0.9920036066249338, -0.005890196345065615,
    0.0, 0.0, 0.0, 1.0,
    0.7006631180123714, 0.7129095423822428, 0.02883018275216084, -0.6384312451306708,
    -0.7131775286122444, 0.6985820318603596, 0.05797376513893045, -1.4384914964435422,
    0.021189802729460493, -0.06118111752978518, 0.9979017301909511, -0.16521114658776714,
    0.0, 0.0, 0.0, 1.0,
};


// ---- make_ring: the graph of record_pose_graph.py, formula for formula ----

Eigen::Matrix3d rot_x(double a) {
    Eigen::Matrix3d r;
    r << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
    return r;
}

Eigen::Matrix3d rot_z(double a) {
    Eigen::Matrix3d r;
    r << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    return r;
}

Eigen::Matrix4d rigid(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = r;
    m.topRightCorner<3, 1>() = t;
    return m;
}

Eigen::Matrix4d rigid_inverse(const Eigen::Matrix4d& m) {
    const Eigen::Matrix3d r = m.topLeftCorner<3, 3>().transpose();
    return rigid(r, -r * m.topRightCorner<3, 1>());
}

Eigen::Matrix3d rodrigues(const Eigen::Vector3d& w) {
    const double theta = std::sqrt(w(0) * w(0) + w(1) * w(1) + w(2) * w(2));
    Eigen::Matrix3d k;
    k << 0, -w(2), w(1), w(2), 0, -w(0), -w(1), w(0), 0;
    k /= theta;
    return Eigen::Matrix3d::Identity() + std::sin(theta) * k + (1.0 - std::cos(theta)) * (k * k);
}

Eigen::Matrix4d ground_truth(int i, int n) {
    const double th = 2.0 * M_PI * i / n;
    return rigid(rot_z(th) * rot_x(0.1 * std::sin(3.0 * th)),
                 {2.0 * std::cos(th) - 2.0, 2.0 * std::sin(th), 0.2 * std::sin(2.0 * th)});
}

Eigen::Matrix4d noise(int k) {
    const Eigen::Vector3d w(0.01 * std::sin(1.3 * k + 0.1), 0.01 * std::cos(2.1 * k + 0.2),
                            0.01 * std::sin(0.7 * k + 0.3));
    const Eigen::Vector3d t(0.01 * std::cos(1.1 * k), 0.01 * std::sin(1.9 * k + 0.5), 0.01 * std::cos(0.3 * k + 0.7));
    return rigid(rodrigues(w), t);
}

reg::Matrix6d information() {
    reg::Matrix6d info = reg::Matrix6d::Zero();
    for (int k = 0; k < 100; ++k) {
        const double x = 2.0 * std::fmod(0.5 + k * 0.7548776662466927, 1.0) - 1.0;
        const double y = 2.0 * std::fmod(0.5 + k * 0.5698402909980532, 1.0) - 1.0;
        const double z = 0.25 * std::sin(3.0 * x) * std::cos(2.0 * y);
        Eigen::Matrix<double, 6, 3> g;
        g << 0, -z, y, z, 0, -x, -y, x, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
        for (int c = 0; c < 3; ++c) info += g.col(c) * g.col(c).transpose();
    }
    return info;
}

struct RingEdge {
    int source, target;
    bool uncertain, wrong;
};

std::vector<RingEdge> ring_edges(int n) {
    std::vector<RingEdge> edges;
    for (int i = 0; i + 1 < n; ++i) edges.push_back({i, i + 1, false, false});
    edges.push_back({n - 1, 0, true, false});
    for (int i = 0; i < n - 3; i += 3) edges.push_back({i + 3, i, true, false});
    edges.push_back({n / 2, 1, true, true});
    return edges;
}

reg::PoseGraph make_ring(int n) {
    std::vector<Eigen::Matrix4d> gt;
    for (int i = 0; i < n; ++i) gt.push_back(ground_truth(i, n));
    const reg::Matrix6d info = information();
    const Eigen::Matrix4d wrong = rigid(rot_z(0.8), {0.6, -0.4, 0.3});
    reg::PoseGraph graph;
    const auto edges = ring_edges(n);
    for (size_t k = 0; k < edges.size(); ++k) {
        const RingEdge& r = edges[k];
        Eigen::Matrix4d m = noise(static_cast<int>(k)) * (rigid_inverse(gt[static_cast<size_t>(r.target)]) *
                                                          gt[static_cast<size_t>(r.source)]);
        if (r.wrong) m = wrong * m;
        graph.edges.push_back({r.source, r.target, m, info, r.uncertain, 1.0});
    }
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
    graph.nodes.push_back({pose});
    for (int i = 0; i + 1 < n; ++i) {
        pose = pose * rigid_inverse(graph.edges[static_cast<size_t>(i)].transformation);  // odometry i -> i + 1
        graph.nodes.push_back({pose});
    }
    return graph;
}

// ---- comparisons ----

Eigen::Matrix4d row_major(const double* m) { return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m); }

double max_abs(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

struct Expected {
    size_t edges;
    const int* ids;
    const double* confidence;
    const double* poses;
};

/// Edges left, their confidences, and the poses: absolute when both runs fixed the same reference node,
/// else relative to node 0 (Open3D leaves reference_node = -1 in whatever frame its solver drifted to).
void expect_matches(const reg::PoseGraph& graph, const Expected& expected, bool absolute, double pose_tolerance,
                    double confidence_tolerance) {
    ASSERT_EQ(graph.edges.size(), expected.edges);
    for (size_t k = 0; k < graph.edges.size(); ++k) {
        SCOPED_TRACE("edge " + std::to_string(k));
        EXPECT_EQ(graph.edges[k].source_node_id, expected.ids[2 * k]);
        EXPECT_EQ(graph.edges[k].target_node_id, expected.ids[2 * k + 1]);
        EXPECT_NEAR(graph.edges[k].confidence, expected.confidence[k], confidence_tolerance);
    }
    const Eigen::Matrix4d our0_inv = rigid_inverse(graph.nodes[0].pose);
    const Eigen::Matrix4d their0_inv = rigid_inverse(row_major(expected.poses));
    for (size_t i = 0; i < graph.nodes.size(); ++i) {
        SCOPED_TRACE("node " + std::to_string(i));
        const Eigen::Matrix4d theirs = row_major(expected.poses + 16 * i);
        if (absolute)
            EXPECT_LT(max_abs(graph.nodes[i].pose - theirs), pose_tolerance);
        else
            EXPECT_LT(max_abs(our0_inv * graph.nodes[i].pose - their0_inv * theirs), pose_tolerance);
    }
}

reg::GlobalOptimizationOptions with(reg::GlobalOptimizationMethod method, int reference_node = -1) {
    reg::GlobalOptimizationOptions options;
    options.method = method;
    options.option.reference_node = reference_node;
    return options;
}

}  // namespace

// Open3D's file is random numbers with an edge to a node that does not exist; what it pins down is the
// layout (column-major matrices, Open3D's field names), read exactly.
TEST(GlobalOptimizationReference, TestPoseGraphFileReadsAsOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/test_pose_graph.json");
    const reg::PoseGraph graph = o3d::io::read_pose_graph(path);
    ASSERT_EQ(graph.nodes.size(), 2u);
    ASSERT_EQ(graph.edges.size(), 2u);
    EXPECT_EQ(graph.nodes[0].pose, row_major(kFileNode0));
    EXPECT_EQ(graph.edges[0].transformation, row_major(kFileEdge0Transformation));
    using RowMajor6 = Eigen::Matrix<double, 6, 6, Eigen::RowMajor>;
    EXPECT_EQ(graph.edges[0].information, reg::Matrix6d(Eigen::Map<const RowMajor6>(kFileEdge0Information)));
    EXPECT_EQ(graph.edges[1].source_node_id, 2);
    EXPECT_FALSE(graph.edges[0].uncertain);
    EXPECT_EQ(graph.edges[0].confidence, 1.0);  // the file has no "confidence": Open3D's default
}

// Open3D warns "graph is not connected" and returns the graph unchanged (the script checks it); we fail
// with InvalidArgument and leave it unchanged as well. (The issue asks for this file's residual to fall;
// it cannot be optimized at all, so the ring below carries that check.)
TEST(GlobalOptimizationReference, TestPoseGraphFileIsRefusedAndLeftUnchanged) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/test_pose_graph.json");
    reg::PoseGraph graph = o3d::io::read_pose_graph(path);
    const reg::PoseGraph before = graph;
    for (auto method :
         {reg::GlobalOptimizationMethod::GaussNewton, reg::GlobalOptimizationMethod::LevenbergMarquardt})
        EXPECT_THROW(reg::global_optimization(graph, with(method)), o3d::InvalidArgument);
    for (size_t i = 0; i < graph.nodes.size(); ++i) EXPECT_EQ(graph.nodes[i].pose, before.nodes[i].pose);
    EXPECT_EQ(graph.edges.size(), before.edges.size());
}

// The C++ ring must be the script's ring, or nothing below compares like with like.
TEST(GlobalOptimizationReference, RingIsBuiltAsInTheScript) {
    const reg::PoseGraph ring = make_ring(8);
    ASSERT_EQ(ring.nodes.size(), 8u);
    ASSERT_EQ(ring.edges.size(), 11u);
    EXPECT_LT(max_abs(ring.nodes[7].pose - row_major(kRingNode7)), 1e-14);
    EXPECT_LT(max_abs(ring.edges.back().transformation - row_major(kRingFalseClosure)), 1e-14);
}

// Levenberg-Marquardt solves the same damped system as Open3D, so the two follow the same path and agree to
// rounding; Gauss-Newton holds the reference node where Open3D's singular solve lets the gauge wander, so
// the two paths differ and agree to the convergence tolerance (1e-6 relative steps).
TEST(GlobalOptimizationReference, RingLevenbergMarquardtMatchesOpen3D) {
    reg::PoseGraph graph = make_ring(8);
    const auto summary = reg::global_optimization(graph, with(reg::GlobalOptimizationMethod::LevenbergMarquardt));
    EXPECT_EQ(summary.pruned_edges, 1);
    expect_matches(graph, {kRingLMEdges, kRingLMEdgeIds, kRingLMConfidence, kRingLMPoses}, false, 1e-12, 1e-12);
}

TEST(GlobalOptimizationReference, RingGaussNewtonMatchesOpen3D) {
    reg::PoseGraph graph = make_ring(8);
    const auto summary = reg::global_optimization(graph, with(reg::GlobalOptimizationMethod::GaussNewton));
    EXPECT_EQ(summary.pruned_edges, 1);
    expect_matches(graph, {kRingGNEdges, kRingGNEdgeIds, kRingGNConfidence, kRingGNPoses}, false, 1e-6, 1e-6);
}

TEST(GlobalOptimizationReference, RingWithReferenceNodeMatchesOpen3D) {
    reg::PoseGraph lm = make_ring(8);
    reg::global_optimization(lm, with(reg::GlobalOptimizationMethod::LevenbergMarquardt, 0));
    expect_matches(lm, {kRingLMRef0Edges, kRingLMRef0EdgeIds, kRingLMRef0Confidence, kRingLMRef0Poses}, true, 1e-12,
                   1e-12);
    reg::PoseGraph gn = make_ring(8);
    reg::global_optimization(gn, with(reg::GlobalOptimizationMethod::GaussNewton, 3));
    expect_matches(gn, {kRingGNRef3Edges, kRingGNRef3EdgeIds, kRingGNRef3Confidence, kRingGNRef3Poses}, true, 1e-6,
                   1e-6);
}

// The ring's objective falls: the reported one, and the plain weighted error of the edges kept, recomputed
// here from the definition e = lin(T^-1 pose_t^-1 pose_s).
TEST(GlobalOptimizationReference, OptimizingTheRingReducesTheResidual) {
    const auto weighted_error = [](const reg::PoseGraph& g, const std::vector<reg::PoseGraphEdge>& edges) {
        double sum = 0.0;
        for (const auto& e : edges) {
            const Eigen::Matrix4d& ps = g.nodes[static_cast<size_t>(e.source_node_id)].pose;
            const Eigen::Matrix4d& pt = g.nodes[static_cast<size_t>(e.target_node_id)].pose;
            const Eigen::Matrix4d m = e.transformation.inverse() * pt.inverse() * ps;
            Eigen::Matrix<double, 6, 1> v;
            v << (m(2, 1) - m(1, 2)) / 2, (m(0, 2) - m(2, 0)) / 2, (m(1, 0) - m(0, 1)) / 2, m(0, 3), m(1, 3), m(2, 3);
            sum += v.dot(e.information * v);
        }
        return sum;
    };
    for (auto method :
         {reg::GlobalOptimizationMethod::GaussNewton, reg::GlobalOptimizationMethod::LevenbergMarquardt}) {
        SCOPED_TRACE(static_cast<int>(method));
        const reg::PoseGraph before = make_ring(8);
        reg::PoseGraph graph = before;
        const auto summary = reg::global_optimization(graph, with(method));
        EXPECT_LT(summary.final_residual, 0.1 * summary.initial_residual);
        EXPECT_GT(summary.iterations, 2);
        const double was = weighted_error(before, graph.edges), is = weighted_error(graph, graph.edges);
        EXPECT_LT(is, 0.2 * was) << was << " -> " << is;
    }
}
