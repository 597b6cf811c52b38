// Quiet NaNs never trap: the thesis's "known problem 2", fixed.
//
// The thesis (Known Problems, 2) reports that operations on its NaN constants raised
// floating-point exceptions on DEC Alphas. In IEEE 754, arithmetic on a *quiet* NaN gives
// a quiet NaN and raises nothing, and so do `==` and `!=`; but an *ordered* comparison
// (`<`, `<=`, `>`, `>=`) with a NaN raises the "invalid" exception. So the tuples must
// never use an ordered comparison on a value that may be NaN.
//
// These tests turn the exceptions into traps (feenableexcept, a glibc extension): any
// operation that raises one kills the test with SIGFPE, which Catch2 reports as a failure.
// Each test computes inside a trap_guard and checks the results after it, with the traps
// off again (Catch2's own comparisons are none of our business).
#include "vl/catch.hh"

#include <fenv.h>

#include <cmath>
#include <sstream>
#include <string>

#include "vl/ray.hh"
#include "vl/tuples.hh"
#include "vl/tuples_based.hh"

using vl::color;
using vl::color_point;
using vl::matrix;
using vl::point;
using vl::vector;

namespace {

/// Traps invalid operations, division by zero and overflow while it lives, and restores
/// the whole floating-point environment (flags and trap mask) when it dies, even when the
/// test throws.
class trap_guard {
public:
    static constexpr int traps = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;

    trap_guard() {
        fegetenv(&saved_);
        feclearexcept(FE_ALL_EXCEPT);
        feenableexcept(traps);
    }
    ~trap_guard() {
        fedisableexcept(traps);
        fesetenv(&saved_);
    }
    trap_guard(const trap_guard&) = delete;
    trap_guard& operator=(const trap_guard&) = delete;

private:
    fenv_t saved_;
};

// The optimiser knows the values of the NaN constants and may compute a result at compile
// time, where no trap can fire, or move a computation past the end of the guard. These two
// barriers stop both: `at_run_time(x)` is x, but the compiler can no longer see its value;
// `computed(x, y, ...)` makes sure x, y, ... have been computed by this point.
template <class T>
T at_run_time(T x) {
    __asm__ __volatile__("" : "+m"(x) : : "memory");
    return x;
}
template <class... T>
void computed(const T&... x) {
    (..., [](const auto& y) { __asm__ __volatile__("" : : "m"(y) : "memory"); }(x));
}

bool all_nan(const color& c) { return std::isnan(c.r) && std::isnan(c.g) && std::isnan(c.b) && std::isnan(c.a); }
bool all_nan(const vector& v) { return std::isnan(v.x) && std::isnan(v.y) && std::isnan(v.z) && std::isnan(v.w); }
bool all_nan(const point& p) { return std::isnan(p.x) && std::isnan(p.y) && std::isnan(p.z) && std::isnan(p.w); }
bool all_nan(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isnan(m(r, c))) return false;
    return true;
}

/// A matrix with a NaN in every element.
matrix nan_matrix() { return {vl::NaN_vector, vl::NaN_vector, vl::NaN_vector, vl::NaN_vector}; }

}  // namespace

// ---------------------------------------------------------------------------------------
// Why the code avoids `<` and `>` on NaN
// ---------------------------------------------------------------------------------------

TEST_CASE("fp: an ordered comparison with NaN raises 'invalid', == and != do not", "[tuples][fp]") {
    // Flags only, no traps: this shows what the traps in the other tests would catch.
    // Each comparison sits between feclearexcept and fetestexcept because its operand is
    // produced there by at_run_time.
    feclearexcept(FE_ALL_EXCEPT);
    const bool less = at_run_time(vl::NaN) < 1.0;
    computed(less);
    CHECK(fetestexcept(FE_INVALID) != 0);

    feclearexcept(FE_ALL_EXCEPT);
    const bool greater = at_run_time(vl::NaN) > 1.0;
    computed(greater);
    CHECK(fetestexcept(FE_INVALID) != 0);

    feclearexcept(FE_ALL_EXCEPT);
    const bool equal = at_run_time(vl::NaN) == 1.0;
    const bool unequal = at_run_time(vl::NaN) != vl::NaN;
    computed(equal, unequal);
    CHECK(fetestexcept(FE_INVALID) == 0);

    // The quiet forms of the ordered comparisons, for code that must order a possible NaN.
    feclearexcept(FE_ALL_EXCEPT);
    const bool quiet_less = std::isless(at_run_time(vl::NaN), 1.0);
    const bool quiet_greater = std::isgreater(at_run_time(vl::NaN), 1.0);
    computed(quiet_less, quiet_greater);
    CHECK(fetestexcept(FE_INVALID) == 0);

    feclearexcept(FE_ALL_EXCEPT);
    CHECK_FALSE((less || greater || equal || quiet_less || quiet_greater));
    CHECK(unequal);
}

TEST_CASE("fp: inside a trap_guard the traps are on, and after it they are off again", "[tuples][fp]") {
    const int before = fegetexcept();
    int inside = 0;
    {
        const trap_guard guard;
        inside = fegetexcept();
    }
    CHECK((inside & trap_guard::traps) == trap_guard::traps);
    CHECK(fegetexcept() == before);
}

// ---------------------------------------------------------------------------------------
// Every operation with NaN operands, under traps
// ---------------------------------------------------------------------------------------

TEST_CASE("fp: color operations on NaN_color never trap", "[tuples][fp][color]") {
    color sum, difference, scaled, scaled_left, divided, filtered, in_place;
    bool equal = true, unequal = false;
    {
        const trap_guard guard;
        const color n = at_run_time(vl::NaN_color), w = at_run_time(vl::WHITE);
        const double d = at_run_time(2.0);
        sum = n + w;
        difference = w - n;
        scaled = n * d;
        scaled_left = d * n;
        divided = n / d;
        filtered = w * n;
        in_place = w;
        in_place += n;
        in_place -= n;
        in_place *= d;
        in_place /= d;
        equal = n == n;
        unequal = n != w;
        computed(sum, difference, scaled, scaled_left, divided, filtered, in_place, equal, unequal);
    }
    CHECK(all_nan(sum));
    CHECK(all_nan(difference));
    CHECK(all_nan(scaled));
    CHECK(all_nan(scaled_left));
    CHECK(all_nan(divided));
    CHECK(all_nan(filtered));
    CHECK(all_nan(in_place));
    CHECK_FALSE(equal);
    CHECK(unequal);
}

TEST_CASE("fp: vector operations on NaN_vector never trap", "[tuples][fp][vector]") {
    vector sum, difference, negated, scaled, scaled_left, divided, cross, in_place, unit;
    double dot = 0, length = 0;
    bool equal = true, unequal = false;
    {
        const trap_guard guard;
        const vector n = at_run_time(vl::NaN_vector), x = at_run_time(vl::VECTOR_DIRECTION[vl::POS_X]);
        const double d = at_run_time(2.0);
        sum = n + x;
        difference = x - n;
        negated = -n;
        scaled = n * d;
        scaled_left = d * n;
        divided = n / d;
        dot = n * x;
        cross = x % n;
        in_place = x;
        in_place += n;
        in_place -= n;
        in_place *= d;
        in_place /= d;
        in_place %= n;
        unit = n.unit();
        length = n.length();
        equal = n == n;
        unequal = n != x;
        computed(sum, difference, negated, scaled, scaled_left, divided, dot, cross, in_place, unit, length,
                 equal, unequal);
    }
    CHECK(all_nan(sum));
    CHECK(all_nan(difference));
    CHECK(all_nan(negated));
    CHECK(all_nan(scaled));
    CHECK(all_nan(scaled_left));
    CHECK(all_nan(divided));
    CHECK(std::isnan(dot));
    CHECK(std::isnan(cross.x));  // a cross product's w is always 0
    CHECK(std::isnan(cross.y));
    CHECK(std::isnan(cross.z));
    CHECK(vl::is_nan(in_place));
    CHECK(all_nan(unit));
    CHECK(std::isnan(length));
    CHECK_FALSE(equal);
    CHECK(unequal);
}

TEST_CASE("fp: the unit of the zero vector is NaN without dividing by zero", "[tuples][fp][vector]") {
    vector unit;
    {
        const trap_guard guard;
        unit = at_run_time(vl::VECTOR_DIRECTION[vl::NO_DIRECTION]).unit();
        computed(unit);
    }
    CHECK(all_nan(unit));
}

TEST_CASE("fp: point operations on NaN_point never trap", "[tuples][fp][point]") {
    point moved, moved_back, in_place, homogenized;
    vector between;
    bool equal = true, unequal = false, equal_to_origin = true;
    {
        const trap_guard guard;
        const point n = at_run_time(vl::NaN_point), origin = at_run_time(point(0, 0, 0));
        const vector v = at_run_time(vector(1, 2, 3)), nv = at_run_time(vl::NaN_vector);
        moved = n + v;
        moved_back = origin - nv;
        between = n - origin;
        in_place = origin;
        in_place += nv;
        in_place -= v;
        homogenized = n.homogenized();
        equal = n == n;
        unequal = n != origin;
        equal_to_origin = origin == n;
        computed(moved, moved_back, between, in_place, homogenized, equal, unequal, equal_to_origin);
    }
    CHECK(all_nan(moved));
    CHECK(all_nan(moved_back));
    CHECK(all_nan(between));
    CHECK(all_nan(in_place));
    CHECK(std::isnan(homogenized.x));
    CHECK(std::isnan(homogenized.y));
    CHECK(std::isnan(homogenized.z));
    CHECK(homogenized.w == 1);
    CHECK_FALSE(equal);
    CHECK(unequal);
    CHECK_FALSE(equal_to_origin);
}

TEST_CASE("fp: the protected point operations on NaN_point never trap", "[tuples][fp][point][homogeneous]") {
    using namespace vl::homogeneous;
    point scaled, scaled_left, divided, cross, cross_left, in_place;
    double dot_pv = 0, dot_vp = 0, dot_pp = 0;
    {
        const trap_guard guard;
        const point n = at_run_time(vl::NaN_point), p = at_run_time(point(1, 2, 3));
        const vector v = at_run_time(vector(1, 0, 0));
        const double d = at_run_time(2.0);
        scaled = n * d;
        scaled_left = d * n;
        divided = n / d;
        dot_pv = n * v;
        dot_vp = v * n;
        dot_pp = p * n;
        cross = p % n;
        cross_left = v % n;
        in_place = n;
        in_place *= d;
        in_place /= d;
        in_place %= v;
        computed(scaled, scaled_left, divided, dot_pv, dot_vp, dot_pp, cross, cross_left, in_place);
    }
    CHECK(all_nan(scaled));
    CHECK(all_nan(scaled_left));
    CHECK(all_nan(divided));
    CHECK(std::isnan(dot_pv));
    CHECK(std::isnan(dot_vp));
    CHECK(std::isnan(dot_pp));
    CHECK(vl::is_nan(cross));
    CHECK(vl::is_nan(cross_left));
    CHECK(vl::is_nan(in_place));
}

TEST_CASE("fp: color_point operations with NaN never trap", "[tuples_based][fp][color_point]") {
    using namespace vl::homogeneous;
    color_point moved, moved_back, homogenized, scaled, divided, crossed, in_place;
    vector between;
    double dot = 0;
    bool equal = true, unequal = false;
    {
        const trap_guard guard;
        const color_point n = at_run_time(color_point(vl::NaN_color, vl::NaN_point));
        const color_point p = at_run_time(color_point(vl::WHITE, point(1, 2, 3)));
        const vector v = at_run_time(vector(1, 0, 0));
        const double d = at_run_time(2.0);
        moved = n + v;
        moved_back = n - v;
        between = p - n;
        homogenized = n.homogenized();
        scaled = d * n;
        divided = n / d;
        dot = n * p;
        crossed = p % n;
        in_place = n;
        in_place += v;
        in_place -= v;
        in_place *= d;
        in_place /= d;
        in_place %= v;
        equal = n == n;
        unequal = n != p;
        computed(moved, moved_back, between, homogenized, scaled, divided, dot, crossed, in_place, equal,
                 unequal);
    }
    CHECK(all_nan(moved.pnt()));
    CHECK(all_nan(moved.clr()));  // the colour is carried along untouched
    CHECK(all_nan(moved_back.pnt()));
    CHECK(all_nan(between));
    CHECK(std::isnan(homogenized.pnt().x));
    CHECK(all_nan(scaled.pnt()));
    CHECK(all_nan(divided.pnt()));
    CHECK(std::isnan(dot));
    CHECK(vl::is_nan(crossed.pnt()));
    CHECK(vl::is_nan(in_place.pnt()));
    CHECK_FALSE(equal);
    CHECK(unequal);
}

TEST_CASE("fp: matrix operations with NaN never trap", "[tuples_based][fp][matrix]") {
    matrix product, product_left, sum, difference, scaled, scaled_left, transposed;
    point transformed_point, nan_point_transformed;
    vector transformed_vector;
    color_point transformed_color_point;
    vl::ray transformed_ray;
    double determinant = 0;
    bool equal = true, unequal = false;
    {
        const trap_guard guard;
        const matrix n = at_run_time(nan_matrix()), identity = at_run_time(vl::IDENTITY);
        const double d = at_run_time(2.0);
        product = identity * n;
        product_left = n * identity;
        sum = n + identity;
        difference = identity - n;
        scaled = n * d;
        scaled_left = d * n;
        transposed = n.transpose();
        determinant = n.determinant();
        transformed_point = n * at_run_time(point(1, 2, 3));
        nan_point_transformed = identity * at_run_time(vl::NaN_point);
        transformed_vector = n * at_run_time(vector(1, 2, 3));
        transformed_color_point = n * at_run_time(color_point(vl::WHITE, point(1, 2, 3)));
        transformed_ray = n * at_run_time(vl::ray(point(0, 0, 0), vector(0, 0, -1)));
        equal = n == n;
        unequal = n != identity;
        computed(product, product_left, sum, difference, scaled, scaled_left, transposed, determinant,
                 transformed_point, nan_point_transformed, transformed_vector, transformed_color_point,
                 transformed_ray, equal, unequal);
    }
    CHECK(all_nan(product));
    CHECK(all_nan(product_left));
    CHECK(all_nan(sum));
    CHECK(all_nan(difference));
    CHECK(all_nan(scaled));
    CHECK(all_nan(scaled_left));
    CHECK(all_nan(transposed));
    CHECK(std::isnan(determinant));
    CHECK(all_nan(transformed_point));
    CHECK(all_nan(nan_point_transformed));
    CHECK(all_nan(transformed_vector));
    CHECK(all_nan(transformed_color_point.pnt()));
    CHECK(transformed_color_point.clr() == vl::WHITE);
    CHECK(all_nan(transformed_ray.origin()));
    CHECK(all_nan(transformed_ray.direction()));
    CHECK_FALSE(equal);
    CHECK(unequal);
}

TEST_CASE("fp: writing and reading NaN tuples never traps", "[tuples][fp][streams]") {
    std::string text;
    color c;
    vector v;
    point p;
    color_point cp;
    matrix m;
    bool read_ok = false;
    {
        const trap_guard guard;
        std::ostringstream out;
        out << at_run_time(vl::NaN_color) << ' ' << at_run_time(vl::NaN_vector) << ' '
            << at_run_time(vl::NaN_point) << ' ' << at_run_time(color_point(vl::NaN_color, vl::NaN_point))
            << ' ' << at_run_time(nan_matrix());
        text = out.str();
        std::istringstream in(text);
        read_ok = static_cast<bool>(in >> c >> v >> p >> cp >> m);
        computed(c, v, p, cp, m);
    }
    CAPTURE(text);
    CHECK(read_ok);
    CHECK(text.starts_with("color (nan, nan, nan, nan) vector (nan, nan, nan, nan) point (nan, nan, nan, nan)"));
    CHECK(all_nan(c));
    CHECK(all_nan(v));
    CHECK(all_nan(p));
    CHECK(all_nan(cp.clr()));
    CHECK(all_nan(cp.pnt()));
    CHECK(all_nan(m));
}
