#include "bullet_drape.h"

#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>

namespace animkit::bench {

namespace {

btVector3 bt(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

// Half the ground slab's thickness and side, m: a static box whose top face is the ground
// plane (Bullet's soft-rigid SDF takes convex shapes only, not btStaticPlaneShape).
constexpr double kSlabHalf = 0.5, kSlabSide = 10.0;

}  // namespace

struct BulletDrape::Impl {
  BulletDrapeSettings settings;
  btSoftBodyRigidBodyCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btSoftRigidDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btSphereShape ball_shape{1.0};
  btBoxShape ground_shape{btVector3(kSlabSide, kSlabHalf, kSlabSide)};
  std::unique_ptr<btRigidBody> ball, ground;
  btSoftBody* cloth = nullptr;  // owned: the world does not delete its bodies
  std::vector<std::array<int, 3>> triangles;
  double spacing = 0.0;

  ~Impl() {
    if (cloth) {
      world.removeSoftBody(cloth);
      delete cloth;
    }
    if (ball) world.removeRigidBody(ball.get());
    if (ground) world.removeRigidBody(ground.get());
  }

  std::unique_ptr<btRigidBody> add_static(btCollisionShape* shape, const btVector3& at,
                                          double friction) {
    btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape);
    info.m_startWorldTransform.setIdentity();
    info.m_startWorldTransform.setOrigin(at);
    info.m_friction = friction;
    auto body = std::make_unique<btRigidBody>(info);
    world.addRigidBody(body.get());
    return body;
  }
};

BulletDrape::BulletDrape(const DrapeParts& parts, const std::array<Vec3, 4>& corners,
                         const BulletDrapeSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.settings = settings;
  const GridClothOptions& sheet = parts.sheet;
  const ClothMaterial& cotton = sheet.material.value();
  const int n = sheet.cells + 1;
  m.spacing = sheet.size / sheet.cells;

  const btVector3 gravity(0.0, -sheet.gravity, 0.0);
  m.world.setGravity(gravity);
  btSoftBodyWorldInfo& info = m.world.getWorldInfo();
  info.m_gravity = gravity;
  info.air_density = 0.0;  // still air, as the scene
  // The SDF samples the ball's distance on a grid and interpolates: voxels of one spacing
  // keep the interpolation error (~ voxel^2 / 8R) well under the margin.
  info.m_sparsesdf.setDefaultVoxelsz(m.spacing);
  info.m_sparsesdf.Reset();

  m.ball_shape.setUnscaledRadius(parts.ball_radius);
  m.ball = m.add_static(&m.ball_shape, bt(parts.ball_centre), parts.ball_friction);
  m.ground = m.add_static(&m.ground_shape, btVector3(0.0, parts.ground_height - kSlabHalf, 0.0),
                          parts.ground_friction);

  m.cloth = btSoftBodyHelpers::CreatePatch(info, bt(corners[0]), bt(corners[1]), bt(corners[2]),
                                           bt(corners[3]), n, n, 0, true);
  btSoftBody& cloth = *m.cloth;
  cloth.getCollisionShape()->setMargin(settings.margin);
  cloth.m_materials[0]->m_kLST = 1.0;
  btSoftBody::Material* shear = cloth.appendMaterial();
  shear->m_kLST = 2.0 * cotton.shear / (cotton.stretch - cotton.shear);
  for (int i = 0; i < cloth.m_links.size(); ++i)
    if (cloth.m_links[i].m_rl > 1.2 * m.spacing) cloth.m_links[i].m_material = shear;
  cloth.m_cfg.piterations = settings.position_iterations;
  cloth.m_cfg.kDP = cotton.damping;
  cloth.m_cfg.kDF = 1.0;
  cloth.m_cfg.collisions = btSoftBody::fCollision::SDF_RS;
  if (settings.self_collision)
    cloth.m_cfg.collisions |= btSoftBody::fCollision::CL_SS | btSoftBody::fCollision::CL_SELF;
  cloth.setTotalMass(cotton.density * sheet.size * sheet.size, true);
  if (settings.self_collision) cloth.generateClusters(0);  // one cluster per triangle
  cloth.updateConstants();
  m.world.addSoftBody(m.cloth);

  const btSoftBody::Node* first = &cloth.m_nodes[0];
  for (int f = 0; f < cloth.m_faces.size(); ++f) {
    const btSoftBody::Face& face = cloth.m_faces[f];
    m.triangles.push_back({static_cast<int>(face.m_n[0] - first),
                           static_cast<int>(face.m_n[1] - first),
                           static_cast<int>(face.m_n[2] - first)});
  }
}

BulletDrape::~BulletDrape() = default;

void BulletDrape::step(double dt) {
  const int substeps = impl_->settings.substeps;
  impl_->world.stepSimulation(dt, substeps, dt / substeps);
}

int BulletDrape::node_count() const {
  return impl_->cloth->m_nodes.size();
}

void BulletDrape::positions(std::vector<Vec3>& out) const {
  const btSoftBody& cloth = *impl_->cloth;
  out.resize(cloth.m_nodes.size());
  for (int i = 0; i < cloth.m_nodes.size(); ++i) {
    const btVector3& x = cloth.m_nodes[i].m_x;
    out[i] = Vec3(x.x(), x.y(), x.z());
  }
}

const std::vector<std::array<int, 3>>& BulletDrape::triangles() const {
  return impl_->triangles;
}

std::array<double, 2> BulletDrape::axis_strain() const {
  const btSoftBody& cloth = *impl_->cloth;
  double sum = 0.0, largest = 0.0;
  int count = 0;
  for (int i = 0; i < cloth.m_links.size(); ++i) {
    const btSoftBody::Link& link = cloth.m_links[i];
    if (link.m_rl > 1.2 * impl_->spacing) continue;  // a diagonal
    const double strain = (link.m_n[0]->m_x - link.m_n[1]->m_x).length() / link.m_rl - 1.0;
    sum += strain;
    largest = std::max(largest, strain);
    ++count;
  }
  return {count ? sum / count : 0.0, largest};
}

}  // namespace animkit::bench
