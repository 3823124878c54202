#pragma once
// Numbers for the accuracy oracle: MPFR at 1024 bits, with value semantics. Within the scene
// loader's supported range (scene.h: magnitudes 1e-50 ... 1e50, exponents within +-167 bits) the
// sum, difference or product of two doubles, or of squares of them, needs at most ~770 bits, so
// the polynomial parts of every test (power of a point, discriminant, plane side) are exact and
// their signs are right even at exactly 0; only square roots, divisions and angles round, at 2^-1024.

#include <mpfr.h>

namespace hexray::oracle {

class Exact {
public:
    static constexpr mpfr_prec_t kBits = 1024;

    Exact() : Exact(0.0) {}
    Exact(double value) {  // implicit: every double is exact here
        mpfr_init2(value_, kBits);
        mpfr_set_d(value_, value, MPFR_RNDN);
    }
    Exact(const Exact& other) {
        mpfr_init2(value_, kBits);
        mpfr_set(value_, other.value_, MPFR_RNDN);
    }
    Exact(Exact&& other) noexcept {
        mpfr_init2(value_, kBits);
        mpfr_swap(value_, other.value_);
    }
    Exact& operator=(const Exact& other) {
        mpfr_set(value_, other.value_, MPFR_RNDN);
        return *this;
    }
    Exact& operator=(Exact&& other) noexcept {
        mpfr_swap(value_, other.value_);
        return *this;
    }
    ~Exact() { mpfr_clear(value_); }

    double toDouble() const { return mpfr_get_d(value_, MPFR_RNDN); }
    int sign() const { return mpfr_sgn(value_); }
    bool isZero() const { return mpfr_zero_p(value_) != 0; }

    friend Exact operator+(const Exact& a, const Exact& b) { return apply(mpfr_add, a, b); }
    friend Exact operator-(const Exact& a, const Exact& b) { return apply(mpfr_sub, a, b); }
    friend Exact operator*(const Exact& a, const Exact& b) { return apply(mpfr_mul, a, b); }
    friend Exact operator/(const Exact& a, const Exact& b) { return apply(mpfr_div, a, b); }
    friend Exact operator-(const Exact& a) { return apply(mpfr_neg, a); }
    friend bool operator<(const Exact& a, const Exact& b) { return mpfr_less_p(a.value_, b.value_) != 0; }
    friend bool operator>(const Exact& a, const Exact& b) { return b < a; }
    friend bool operator<=(const Exact& a, const Exact& b) { return !(b < a); }
    friend bool operator==(const Exact& a, const Exact& b) { return mpfr_equal_p(a.value_, b.value_) != 0; }

    friend Exact sqrt(const Exact& a) { return apply(mpfr_sqrt, a); }
    friend Exact abs(const Exact& a) { return apply(mpfr_abs, a); }
    friend Exact floor(const Exact& a) {
        Exact result;
        mpfr_floor(result.value_, a.value_);
        return result;
    }
    friend Exact atan2(const Exact& y, const Exact& x) { return apply(mpfr_atan2, y, x); }
    // x mod 2 for an integer x: 0 or 1 (or -1), exact at any magnitude.
    friend bool isOdd(const Exact& integer) {
        Exact result;
        mpfr_fmod(result.value_, integer.value_, Exact(2.0).value_, MPFR_RNDN);
        return !result.isZero();
    }
    static Exact pi() {
        Exact result;
        mpfr_const_pi(result.value_, MPFR_RNDN);
        return result;
    }

private:
    using Unary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
    using Binary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
    static Exact apply(Unary operation, const Exact& a) {
        Exact result;
        operation(result.value_, a.value_, MPFR_RNDN);
        return result;
    }
    static Exact apply(Binary operation, const Exact& a, const Exact& b) {
        Exact result;
        operation(result.value_, a.value_, b.value_, MPFR_RNDN);
        return result;
    }

    mpfr_t value_;
};

inline Exact min(const Exact& a, const Exact& b) {
    return b < a ? b : a;
}
inline Exact max(const Exact& a, const Exact& b) {
    return a < b ? b : a;
}

struct ExactVec {
    Exact x, y, z;

    friend ExactVec operator+(const ExactVec& a, const ExactVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend ExactVec operator-(const ExactVec& a, const ExactVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend ExactVec operator*(const Exact& s, const ExactVec& v) { return {s * v.x, s * v.y, s * v.z}; }
    friend ExactVec operator-(const ExactVec& v) { return {-v.x, -v.y, -v.z}; }
};

inline Exact dot(const ExactVec& a, const ExactVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Exact length(const ExactVec& v) {
    return sqrt(dot(v, v));
}

}  // namespace hexray::oracle
