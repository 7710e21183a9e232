#include "sim/render/table_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

namespace billiard::render {
namespace {

// OpenCV's BGR -> gray weights, so that a gray frame is what cvtColor would make of a colour one.
float Luma(const Eigen::Vector3f& bgr) {
  return 0.114f * bgr[0] + 0.587f * bgr[1] + 0.299f * bgr[2];
}

Eigen::Vector3f ToVector(const cv::Vec3b& c) { return {float(c[0]), float(c[1]), float(c[2])}; }

// The light's gain per channel (RenderOptions::light_colour), B, G, R.
Eigen::Vector3f LightGain(const RenderOptions& options) {
  const cv::Vec3f& c = options.light_colour;
  return {c[0], c[1], c[2]};
}

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Distinct offsets into the noise buffer: how many frames pass before two share their noise.
constexpr std::size_t kNoiseOffsets = std::size_t{1} << 20;

// Where the soft contact shadow ends, in ball radii from the contact point: most of it lies under
// the ball, and the reach sets the size of the boxes a frame renders.
constexpr double kShadowReach = 1.5;

struct Hit {
  double depth;  // along the ray to the point closest to the ball's centre
  float coverage;
  int ball;
  double miss;  // distance of the ray from the ball's centre
};

}  // namespace

RenderBall RenderBall::AtRest(int id, const cv::Vec3b& colour, const Eigen::Vector2d& xy) {
  return {id, colour, [xy](double) { return xy; }};
}

RenderBall RenderBall::Following(int id, const cv::Vec3b& colour,
                                 std::shared_ptr<const physics::Trajectory> trajectory) {
  return {id, colour, [trajectory](double t) {
            const physics::BallState s = trajectory->At(t);
            return Eigen::Vector2d(s[physics::kX], s[physics::kY]);
          }};
}

cv::Vec3b PoolBallColour(int id) {
  static const cv::Vec3b kColours[9] = {
      {225, 240, 245},  // cue ball, ivory
      {20, 200, 250},   // yellow
      {170, 50, 20},    // blue
      {30, 30, 210},    // red
      {120, 30, 90},    // purple
      {20, 110, 250},   // orange
      {40, 95, 0},      // green: darker and more saturated than the cloth, as real 6-balls are
      {30, 25, 120},    // maroon
      {20, 20, 20}};    // black
  if (id < 0 || id > 15) throw std::invalid_argument("pool balls are numbered 0..15");
  return kColours[id <= 8 ? id : id - 8];
}

// The balls whose boxes overlap, rendered together so that they occlude each other.
struct TableRenderer::Region {
  struct Sample {
    Eigen::Vector3d centre;
    double footprint;  // a pixel's width at the ball [m]: the anti-aliasing ramp
  };
  cv::Rect box;
  int subframes = 1;
  double pixel_angle = 0;               // between neighbouring pixels' rays near the balls [rad]
  std::vector<Eigen::Vector3f> albedo;  // per ball
  std::vector<bool> striped;            // per ball
  std::vector<Eigen::Vector3d> axis, spot;  // per ball (RenderBall's)
  std::vector<Sample> samples;          // subframe-major: samples[s * balls + k]
  int balls() const { return static_cast<int>(albedo.size()); }
};

TableRenderer::TableRenderer(const camera::CameraModel& camera,
                             const physics::ModelParameters& params, const RenderOptions& options)
    : camera_(camera),
      radius_(params.ball.radius),
      table_(params.table),
      options_(options),
      centre_(camera.Centre()) {
  const int w = camera.width, h = camera.height;
  if (w < 2 || h < 2) throw std::invalid_argument("TableRenderer: the camera has no image");
  if (!(radius_ > 0) || !(table_.length > 0) || !(table_.width > 0)) {
    throw std::invalid_argument("TableRenderer: ball radius and table size must be positive");
  }
  if (options.subframes < 1 || !(options.exposure_s >= 0) || !(options.noise_sigma >= 0)) {
    throw std::invalid_argument(
        "TableRenderer: need subframes >= 1, exposure >= 0 and noise sigma >= 0");
  }
  for (int c = 0; c < 3; ++c) {
    if (!(options.light_colour[c] >= 0) || !std::isfinite(options.light_colour[c])) {
      throw std::invalid_argument("TableRenderer: the light's colour must be finite, >= 0");
    }
  }
  if (!(centre_.z() > options.cushion_height)) {
    throw std::invalid_argument("TableRenderer: the camera must be above the cushions");
  }
  options_.light_direction.normalize();
  const double corner2 = 0.25 * ((w - 1.0) * (w - 1.0) + (h - 1.0) * (h - 1.0));
  vignette_scale_ = static_cast<float>(options.vignetting / corner2);

  rays_.resize(static_cast<std::size_t>(w) * h);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) rays_[v * w + u] = camera.Ray({u, v});
  }

  // The background, 3x3 supersampled. The sub-pixel rays are interpolated between pixel centres
  // (the lens is smooth on that scale), which spares 8 undistortions per pixel.
  const auto ray_at = [&](double u, double v) {
    const int i = std::clamp(static_cast<int>(std::floor(u)), 0, w - 2);
    const int j = std::clamp(static_cast<int>(std::floor(v)), 0, h - 2);
    const double a = u - i, b = v - j;
    const Eigen::Vector3d r = (1 - b) * ((1 - a) * RayAt(i, j) + a * RayAt(i + 1, j)) +
                              b * ((1 - a) * RayAt(i, j + 1) + a * RayAt(i + 1, j + 1));
    return r.normalized();
  };
  const double ch = options.cushion_height, L = table_.length, W = table_.width;
  const double cushion_out = options.cushion_width, rail_out = cushion_out + options.rail_width;
  // How far (x, y) lies outside the playing surface (Chebyshev distance; 0 inside).
  const auto outside = [&](double x, double y) { return std::max({-x, x - L, -y, y - W, 0.0}); };
  const Eigen::Vector3f light = LightGain(options);
  const auto lambert = [&](const cv::Vec3b& albedo, const Eigen::Vector3d& normal) {
    const double lit = options.ambient +
                       (1 - options.ambient) * std::max(0.0, normal.dot(options_.light_direction));
    return Eigen::Vector3f(ToVector(albedo).cwiseProduct(light) * static_cast<float>(lit));
  };
  const auto table_colour = [&](const Eigen::Vector3d& d) -> Eigen::Vector3f {
    if (d.z() >= 0) return lambert(options.floor, Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d top = centre_ + (ch - centre_.z()) / d.z() * d;
    const double out_top = outside(top.x(), top.y());
    if (out_top > 0) {
      const cv::Vec3b& c = out_top <= cushion_out ? options.cushion
                           : out_top <= rail_out  ? options.rail
                                                  : options.floor;
      return lambert(c, Eigen::Vector3d::UnitZ());
    }
    const Eigen::Vector3d cloth = centre_ - centre_.z() / d.z() * d;
    if (outside(cloth.x(), cloth.y()) == 0) return lambert(options.cloth, Eigen::Vector3d::UnitZ());
    // The ray enters a cushion's inner face between z = ch and 0: the face it crosses first.
    double first = 1e300;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (const auto& [axis, bound, sign] :
         {std::tuple{0, L, -1.0}, {0, 0.0, 1.0}, {1, W, -1.0}, {1, 0.0, 1.0}}) {
      if (d[axis] == 0) continue;
      const double s = (bound - centre_[axis]) / d[axis];
      const Eigen::Vector3d p = centre_ + s * d;
      if (p.z() <= ch && p.z() >= 0 && s < first) {
        first = s;
        normal = sign * Eigen::Vector3d::Unit(axis);
      }
    }
    return lambert(options.cushion, normal);
  };
  background_.create(h, w, options.gray ? CV_8UC1 : CV_8UC3);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      Eigen::Vector3f sum = Eigen::Vector3f::Zero();
      for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) sum += table_colour(ray_at(u + i / 3.0, v + j / 3.0));
      }
      const Eigen::Vector3f c = sum * (Vignette(u, v) / 9.0f);
      if (options.gray) {
        background_.at<std::uint8_t>(v, u) = cv::saturate_cast<std::uint8_t>(Luma(c));
      } else {
        background_.at<cv::Vec3b>(v, u) =
            cv::Vec3b(cv::saturate_cast<std::uint8_t>(c[0]), cv::saturate_cast<std::uint8_t>(c[1]),
                      cv::saturate_cast<std::uint8_t>(c[2]));
      }
    }
  }

  if (options.noise_sigma > 0) {
    std::mt19937_64 rng(options.seed);
    std::normal_distribution<float> normal(0.0f, static_cast<float>(options.noise_sigma));
    noise_.resize(background_.total() * background_.elemSize() + kNoiseOffsets);
    for (auto& n : noise_)
      n = static_cast<std::int8_t>(std::clamp(std::lround(normal(rng)), -127L, 127L));
  }
}

float TableRenderer::Vignette(int u, int v) const {
  const float hu = 0.5f * (camera_.width - 1), hv = 0.5f * (camera_.height - 1);
  const float du = u - hu, dv = v - hv;
  return 1.0f - vignette_scale_ * (du * du + dv * dv);
}

cv::Mat TableRenderer::Render(const std::vector<RenderBall>& balls, double t) const {
  cv::Mat frame;
  Render(balls, t, &frame);
  return frame;
}

void TableRenderer::Render(const std::vector<RenderBall>& balls, double t, cv::Mat* frame) const {
  background_.copyTo(*frame);
  const int n = options_.exposure_s > 0 ? options_.subframes : 1;
  const double r = radius_;
  const cv::Rect image(0, 0, camera_.width, camera_.height);

  // Each ball's centres over the exposure and the pixels it and its shadow can touch.
  struct Placed {
    std::vector<Eigen::Vector3d> centres;
    bool moves = false;
    cv::Rect box;
    int ball;
  };
  std::vector<Placed> placed;
  for (int k = 0; k < static_cast<int>(balls.size()); ++k) {
    Placed p;
    p.ball = k;
    double u0 = 1e300, v0 = 1e300, u1 = -1e300, v1 = -1e300;
    for (int s = 0; s < n; ++s) {
      const double ts = t + options_.exposure_s * ((s + 0.5) / n - 0.5);
      const Eigen::Vector2d xy = balls[k].position(ts);
      if (!xy.allFinite())
        throw std::invalid_argument("TableRenderer: a ball's position is not finite");
      p.centres.emplace_back(xy.x(), xy.y(), r);
      p.moves = p.moves || (p.centres.back() - p.centres.front()).norm() > 1e-9;
      // The corners of the box around the ball and its shadow bound their projection.
      for (int c = 0; c < 8; ++c) {
        const double reach = kShadowReach * r;
        const Eigen::Vector2d q =
            camera_.Project({xy.x() + (c & 1 ? reach : -reach), xy.y() + (c & 2 ? reach : -reach),
                             c & 4 ? 2 * r : 0.0});
        u0 = std::min(u0, q.x()), u1 = std::max(u1, q.x());
        v0 = std::min(v0, q.y()), v1 = std::max(v1, q.y());
      }
    }
    // Two pixels of margin for the anti-aliasing ramp and the lens's curvature of straight edges.
    const cv::Rect box(
        cv::Point(static_cast<int>(std::floor(u0)) - 2, static_cast<int>(std::floor(v0)) - 2),
        cv::Point(static_cast<int>(std::ceil(u1)) + 3, static_cast<int>(std::ceil(v1)) + 3));
    p.box = box & image;
    if (!p.moves) p.centres.resize(1);
    if (!p.box.empty()) placed.push_back(std::move(p));
  }

  // Overlapping boxes merge into one region, until no two regions overlap.
  std::vector<std::vector<const Placed*>> groups;
  std::vector<cv::Rect> boxes;
  for (const Placed& p : placed) {
    groups.push_back({&p});
    boxes.push_back(p.box);
  }
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < boxes.size() && !merged; ++a) {
      for (std::size_t b = a + 1; b < boxes.size() && !merged; ++b) {
        if ((boxes[a] & boxes[b]).empty()) continue;
        boxes[a] |= boxes[b];
        groups[a].insert(groups[a].end(), groups[b].begin(), groups[b].end());
        boxes.erase(boxes.begin() + b);
        groups.erase(groups.begin() + b);
        merged = true;
      }
    }
  }

  for (std::size_t g = 0; g < groups.size(); ++g) {
    Region region;
    region.box = boxes[g];
    region.subframes = 1;
    for (const Placed* p : groups[g]) {
      region.albedo.push_back(ToVector(balls[p->ball].colour));
      region.striped.push_back(balls[p->ball].striped);
      region.axis.push_back(balls[p->ball].axis);
      region.spot.push_back(balls[p->ball].spot);
      if (p->moves) region.subframes = n;
    }
    for (int s = 0; s < region.subframes; ++s) {
      for (const Placed* p : groups[g]) {
        const Eigen::Vector3d& c = p->centres[p->moves ? s : 0];
        // The ray step between neighbouring pixels near the ball's image, at the ball's distance.
        const Eigen::Vector2d q = camera_.Project(c);
        const int u = std::clamp(static_cast<int>(std::lround(q.x())), 0, camera_.width - 2);
        const int v = std::clamp(static_cast<int>(std::lround(q.y())), 0, camera_.height - 2);
        const double angle =
            0.5 * ((RayAt(u + 1, v) - RayAt(u, v)).norm() + (RayAt(u, v + 1) - RayAt(u, v)).norm());
        region.samples.push_back({c, (c - centre_).norm() * angle});
        region.pixel_angle = angle;
      }
    }
    RenderRegion(region, frame);
  }
  AddNoise(t, frame);
}

TableRenderer::CushionCover TableRenderer::CoverAt(const Eigen::Vector3d& d,
                                                  double pixel_angle) const {
  if (d.z() >= 0) return {};
  const double distance = (options_.cushion_height - centre_.z()) / d.z();
  const Eigen::Vector3d top = centre_ + distance * d;
  // How far beyond each side the ray comes down, for the sides the camera is beyond (a camera
  // above the playing surface sees every ball in front of the cushions).
  const double L = table_.length, W = table_.width;
  const std::array<std::pair<double, double>, 4> beyond_side = {
      {{-top.x(), -centre_.x()}, {top.x() - L, centre_.x() - L},
       {-top.y(), -centre_.y()}, {top.y() - W, centre_.y() - W}}};
  // The nose's edge anti-aliased as a ball's is: a ramp of one pixel's width at that distance.
  const double footprint = std::max(pixel_angle * distance, 1e-12);
  float share = 0;
  for (const auto& [beyond, camera_beyond] : beyond_side) {
    if (camera_beyond > 0) {
      share = std::max(share, static_cast<float>(std::clamp(0.5 + beyond / footprint, 0.0, 1.0)));
    }
  }
  return {distance, share};
}

// The colour of ball `k`'s surface where its normal is `normal`: a number's circle and figure
// around either end of its spot, a stripe's ivory cap beyond its band, else its colour.
const Eigen::Vector3f& TableRenderer::SurfaceColour(const Region& region, int k,
                                                    const Eigen::Vector3d& normal,
                                                    const Eigen::Vector3f& ivory,
                                                    const Eigen::Vector3f& figure) {
  const double to_spot = std::abs(normal.dot(region.spot[k]));
  if (to_spot > std::cos(kFigureRadius)) return figure;
  if (to_spot > std::cos(kSpotRadius)) return ivory;
  const bool cap = region.striped[k] && std::abs(normal.dot(region.axis[k])) > kStripeHalfWidth;
  return cap ? ivory : region.albedo[k];
}

void TableRenderer::RenderRegion(const Region& region, cv::Mat* frame) const {
  const double r = radius_, r2 = r * r;
  const double shadow_reach2 = kShadowReach * kShadowReach * r2;
  const Eigen::Vector3d& light = options_.light_direction;
  const float diffuse = static_cast<float>(1 - options_.ambient);
  const int k_balls = region.balls();
  // Below this cosine the highlight is under half a gray level: no pow() for most of the ball.
  const double highlight_from =
      std::pow(0.5 / (255.0 * std::max(options_.specular, 1e-12)), 1.0 / options_.shininess);
  const Eigen::Vector3f stripe_cap = ToVector(PoolBallColour(0));  // ivory, as the cue ball
  const Eigen::Vector3f figure = ToVector(PoolBallColour(8));      // a number's black
  const Eigen::Vector3f light_gain = LightGain(options_);
  std::vector<Hit> hits;
  hits.reserve(k_balls);
  for (int v = region.box.y; v < region.box.y + region.box.height; ++v) {
    for (int u = region.box.x; u < region.box.x + region.box.width; ++u) {
      const Eigen::Vector3d& d = RayAt(u, v);
      const Eigen::Vector3f bg = options_.gray
                                     ? Eigen::Vector3f::Constant(frame->at<std::uint8_t>(v, u))
                                     : ToVector(frame->at<cv::Vec3b>(v, u));
      // Where the ray meets the cloth (the shadows fall there); far away if it looks up.
      const double to_cloth = d.z() < 0 ? -centre_.z() / d.z() : 1e6;
      const Eigen::Vector2d cloth = centre_.head<2>() + to_cloth * d.head<2>();
      const CushionCover cover = CoverAt(d, region.pixel_angle);
      const float vignette = Vignette(u, v);
      Eigen::Vector3f sum = Eigen::Vector3f::Zero();
      for (int s = 0; s < region.subframes; ++s) {
        const Region::Sample* sample = &region.samples[s * k_balls];
        float lit = 1.0f;
        hits.clear();
        for (int k = 0; k < k_balls; ++k) {
          const Eigen::Vector3d& c = sample[k].centre;
          const double rho2 = (cloth - c.head<2>()).squaredNorm();
          if (rho2 < shadow_reach2) {
            const double fade = 1 - rho2 / shadow_reach2;
            lit *= static_cast<float>(1 - options_.shadow * fade * fade);
          }
          const Eigen::Vector3d to_centre = c - centre_;
          const double depth = d.dot(to_centre);
          const double miss2 = std::max(0.0, to_centre.squaredNorm() - depth * depth);
          const double ramp = sample[k].footprint;
          if (depth <= 0 || miss2 >= (r + 0.5 * ramp) * (r + 0.5 * ramp)) continue;
          const double miss = std::sqrt(miss2);
          float coverage = static_cast<float>(std::clamp(0.5 + (r - miss) / ramp, 0.0, 1.0));
          if (depth - std::sqrt(std::max(0.0, r2 - miss2)) > cover.distance) {
            coverage *= 1.0f - cover.share;
          }
          if (coverage > 0) hits.push_back({depth, coverage, k, miss});
        }
        Eigen::Vector3f colour = bg * lit;
        // Far to near, each ball over what lies behind it.
        if (hits.size() > 1) {
          std::sort(hits.begin(), hits.end(),
                    [](const Hit& a, const Hit& b) { return a.depth > b.depth; });
        }
        for (const Hit& hit : hits) {
          const Eigen::Vector3d& c = sample[hit.ball].centre;
          // The visible surface point; for a ray just missing the ball (the outer half of the
          // anti-aliasing ramp), the limb point nearest to the ray.
          const Eigen::Vector3d normal =
              hit.miss < r
                  ? ((centre_ + (hit.depth - std::sqrt(r2 - hit.miss * hit.miss)) * d - c) / r)
                        .eval()
                  : (centre_ + hit.depth * d - c).normalized();
          const double half = std::max(0.0, normal.dot((light - d).normalized()));
          const float lambert = static_cast<float>(options_.ambient) +
                                diffuse * static_cast<float>(std::max(0.0, normal.dot(light)));
          const float highlight = half > highlight_from
                                      ? static_cast<float>(255.0 * options_.specular *
                                                           std::pow(half, options_.shininess))
                                      : 0.0f;
          const Eigen::Vector3f& albedo =
              SurfaceColour(region, hit.ball, normal, stripe_cap, figure);
          const Eigen::Vector3f ball = (albedo * lambert +
                                        Eigen::Vector3f::Constant(highlight))
                                           .cwiseProduct(light_gain) *
                                       vignette;
          colour = hit.coverage * ball + (1 - hit.coverage) * colour;
        }
        sum += colour;
      }
      sum /= static_cast<float>(region.subframes);
      if (options_.gray) {
        frame->at<std::uint8_t>(v, u) = cv::saturate_cast<std::uint8_t>(Luma(sum));
      } else {
        frame->at<cv::Vec3b>(v, u) = cv::Vec3b(cv::saturate_cast<std::uint8_t>(sum[0]),
                                               cv::saturate_cast<std::uint8_t>(sum[1]),
                                               cv::saturate_cast<std::uint8_t>(sum[2]));
      }
    }
  }
}

void TableRenderer::AddNoise(double t, cv::Mat* frame) const {
  if (noise_.empty()) return;
  const auto utime = static_cast<std::uint64_t>(std::llround(t * 1e6));
  const std::size_t offset = SplitMix64(options_.seed ^ SplitMix64(utime)) % kNoiseOffsets;
  // restrict: char pointers may alias anything, which would keep the loop from vectorizing.
  const std::int8_t* __restrict noise = noise_.data() + offset;
  std::uint8_t* __restrict p = frame->data;  // continuous: a copy of the background
  const std::size_t bytes = frame->total() * frame->elemSize();
  for (std::size_t i = 0; i < bytes; ++i) {
    const int x = p[i] + noise[i];
    p[i] = static_cast<std::uint8_t>(std::clamp(x, 0, 255));
  }
}

}  // namespace billiard::render
