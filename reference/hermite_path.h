// A Hermite path of the reference world's path constraint (spec 3, Path),
// written from the formulas of kernels/hermite_path-inl.h's header comment
// (Jolt's PathConstraintPathHermite): the closest point by bisection then
// Newton, and the point, tangent, normal and binormal at a fraction.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "manyworlds/scene.h"
#include "reference/math.h"
#include "reference/world_setup.h"

namespace manyworlds::reference {

template <class T>
class HermitePath {
 public:
  struct Frame {
    Vec3<T> position, tangent, normal, binormal;
  };

  HermitePath(const std::vector<PathPoint>& points, bool looping) : looping_(looping) {
    for (const PathPoint& p : points) {
      points_.push_back({ToVec3<T>(p.position), ToVec3<T>(p.tangent), ToVec3<T>(p.normal)});
    }
  }

  bool looping() const { return looping_; }
  std::size_t count() const { return points_.size(); }
  std::size_t segments() const { return looping_ ? count() : count() - 1; }
  T max_fraction() const { return T(segments()); }

  T ClosestPoint(const Vec3<T>& q) const {
    T best_distance = (points_.back().position - q).squaredNorm();
    T best_fraction = T(count() - 1);
    for (std::size_t i = 0; i < segments(); ++i) {
      const Segment s = SegmentRelativeTo(i, q);
      const T to_start = s.p1.squaredNorm();
      if (to_start < best_distance) {
        best_fraction = T(i);
        best_distance = to_start;
      }
      T t_min, t_max;
      Bracket(s, t_min, t_max);
      if (t_min == t_max) {
        Vec3<T> position, tangent;
        PositionAndTangent(s, t_min, position, tangent);
        const T distance = position.squaredNorm();
        if (distance < best_distance) {
          best_fraction = T(i) + t_min;
          best_distance = distance;
        }
      } else {
        T distance;
        const T t = Newton(s, t_min, t_max, distance);
        if (t >= T(0) && t <= T(1) && distance < best_distance) {
          best_fraction = T(i) + t;
          best_distance = distance;
        }
      }
    }
    return best_fraction;
  }

  Frame PointOnPath(T fraction) const {
    long index = long(std::trunc(fraction));
    T t = fraction - T(index);
    const long n = long(count());
    if (looping_) {
      if (index < 0) index += (-index / n + 1) * n;
      index %= n;
    } else if (index < 0) {
      index = 0;
      t = T(0);
    } else if (index >= n - 1) {
      index = n - 2;
      t = T(1);
    }
    const Segment s = SegmentRelativeTo(std::size_t(index), Vec3<T>::Zero());
    Frame frame;
    Vec3<T> tangent;
    PositionAndTangent(s, t, frame.position, tangent);
    frame.tangent = tangent.normalized();
    const Vec3<T> normal = (T(1) - t) * points_[std::size_t(index)].normal +
                           t * points_[std::size_t((index + 1) % n)].normal;
    frame.binormal = normal.cross(frame.tangent).normalized();
    frame.normal = frame.tangent.cross(frame.binormal);
    return frame;
  }

 private:
  struct Point {
    Vec3<T> position, tangent, normal;
  };
  struct Segment {
    Vec3<T> p1, m1, p2, m2;
  };

  Segment SegmentRelativeTo(std::size_t i, const Vec3<T>& q) const {
    const Point& a = points_[i];
    const Point& b = points_[(i + 1) % count()];
    return {a.position - q, a.tangent, b.position - q, b.tangent};
  }

  static void PositionAndTangent(const Segment& s, T t, Vec3<T>& position, Vec3<T>& tangent) {
    const T t2 = t * t, t3 = t * t2;
    const T h00 = T(2) * t3 - T(3) * t2 + T(1), h10 = t3 - T(2) * t2 + t;
    const T h01 = T(3) * t2 - T(2) * t3, h11 = t3 - t2;
    const T d00 = T(6) * (t2 - t), d10 = T(3) * t2 - T(4) * t + T(1);
    const T d11 = T(3) * t2 - T(2) * t;
    position = h00 * s.p1 + h10 * s.m1 + h01 * s.p2 + h11 * s.m2;
    tangent = d00 * s.p1 + d10 * s.m1 - d00 * s.p2 + d11 * s.m2;
  }

  static bool NearZero(T x) { return std::abs(x) < T(1.0e-6); }

  static void Bracket(const Segment& s, T& t_min, T& t_max) {
    t_min = T(0);
    t_max = T(1);
    const T f_min = s.p1.dot(s.m1);
    if (NearZero(f_min)) {
      t_max = T(0);
      return;
    }
    const T f_max = s.p2.dot(s.m2);
    if (NearZero(f_max)) {
      t_min = T(1);
      return;
    }
    const bool min_negative = f_min < T(0);
    if (min_negative == (f_max < T(0))) return;
    for (int iteration = 0; iteration < 4; ++iteration) {
      const T t_mid = T(0.5) * (t_min + t_max);
      Vec3<T> position, tangent;
      PositionAndTangent(s, t_mid, position, tangent);
      const T f_mid = position.dot(tangent);
      if (NearZero(f_mid)) {
        t_min = t_max = t_mid;
        return;
      }
      if ((f_mid < T(0)) == min_negative) {
        t_min = t_mid;
      } else {
        t_max = t_mid;
      }
    }
  }

  static T Newton(const Segment& s, T t_min, T t_max, T& distance_squared) {
    const T interval = t_max - t_min;
    T t = T(0.5) * (t_min + t_max);
    Vec3<T> position = Vec3<T>::Zero();
    for (int iteration = 0; iteration < 10; ++iteration) {
      Vec3<T> tangent;
      PositionAndTangent(s, t, position, tangent);
      const T f = position.dot(tangent);
      const Vec3<T> second = (T(12) * t - T(6)) * s.p1 + (T(6) * t - T(4)) * s.m1 -
                             (T(12) * t - T(6)) * s.p2 + (T(6) * t - T(2)) * s.m2;
      const T f_prime = tangent.dot(tangent) + position.dot(second);
      if (f_prime == T(0)) break;
      const T delta = std::min(std::max(-f / f_prime, -interval), interval);
      if ((t > t_max && delta > T(0)) || (t < t_min && delta < T(0))) break;
      t += delta;
      if (std::abs(delta) < T(1.0e-4)) break;
    }
    distance_squared = position.squaredNorm();
    return t;
  }

  std::vector<Point> points_;
  bool looping_;
};

}  // namespace manyworlds::reference
