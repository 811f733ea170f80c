// Mathematical constants as variable templates (C_PI<T>) plus float (suffix f) and double (suffix d) shortcuts.
// Each value is written as a long-double literal and rounded once to T.
#pragma once

namespace rtl
{
    template<typename T> inline constexpr T C_E = static_cast<T>(2.718281828459045235360287471352662498L);
    template<typename T> inline constexpr T C_LOG2E = static_cast<T>(1.442695040888963407359924681001892137L);
    template<typename T> inline constexpr T C_LOG10E = static_cast<T>(0.434294481903251827651128918916605082L);
    template<typename T> inline constexpr T C_LN2 = static_cast<T>(0.693147180559945309417232121458176568L);
    template<typename T> inline constexpr T C_LN10 = static_cast<T>(2.302585092994045684017991454684364208L);
    template<typename T> inline constexpr T C_PI = static_cast<T>(3.141592653589793238462643383279502884L);
    template<typename T> inline constexpr T C_PI_2 = static_cast<T>(1.570796326794896619231321691639751442L);
    template<typename T> inline constexpr T C_PI_4 = static_cast<T>(0.785398163397448309615660845819875721L);
    template<typename T> inline constexpr T C_1_PI = static_cast<T>(0.318309886183790671537767526745028724L);
    template<typename T> inline constexpr T C_2_PI = static_cast<T>(0.636619772367581343075535053490057448L);
    template<typename T> inline constexpr T C_2_SQRTPI = static_cast<T>(1.128379167095512573896158903121545172L);
    template<typename T> inline constexpr T C_SQRT2 = static_cast<T>(1.414213562373095048801688724209698079L);
    template<typename T> inline constexpr T C_SQRT1_2 = static_cast<T>(0.707106781186547524400844362104849039L);

    inline constexpr auto C_Ef = C_E<float>;
    inline constexpr auto C_LOG2Ef = C_LOG2E<float>;
    inline constexpr auto C_LOG10Ef = C_LOG10E<float>;
    inline constexpr auto C_LN2f = C_LN2<float>;
    inline constexpr auto C_LN10f = C_LN10<float>;
    inline constexpr auto C_PIf = C_PI<float>;
    inline constexpr auto C_PI_2f = C_PI_2<float>;
    inline constexpr auto C_PI_4f = C_PI_4<float>;
    inline constexpr auto C_1_PIf = C_1_PI<float>;
    inline constexpr auto C_2_PIf = C_2_PI<float>;
    inline constexpr auto C_2_SQRTPIf = C_2_SQRTPI<float>;
    inline constexpr auto C_SQRT2f = C_SQRT2<float>;
    inline constexpr auto C_SQRT1_2f = C_SQRT1_2<float>;

    inline constexpr auto C_Ed = C_E<double>;
    inline constexpr auto C_LOG2Ed = C_LOG2E<double>;
    inline constexpr auto C_LOG10Ed = C_LOG10E<double>;
    inline constexpr auto C_LN2d = C_LN2<double>;
    inline constexpr auto C_LN10d = C_LN10<double>;
    inline constexpr auto C_PId = C_PI<double>;
    inline constexpr auto C_PI_2d = C_PI_2<double>;
    inline constexpr auto C_PI_4d = C_PI_4<double>;
    inline constexpr auto C_1_PId = C_1_PI<double>;
    inline constexpr auto C_2_PId = C_2_PI<double>;
    inline constexpr auto C_2_SQRTPId = C_2_SQRTPI<double>;
    inline constexpr auto C_SQRT2d = C_SQRT2<double>;
    inline constexpr auto C_SQRT1_2d = C_SQRT1_2<double>;
}
