// Small build-mode query and a generic string-to-number conversion.
#pragma once

#include <cstdlib>
#include <string>

namespace rtl
{
    enum CompModes
    {
        DebugMode = 0,
        ReleaseMode
    };

    //! ReleaseMode when NDEBUG is defined, DebugMode otherwise.
    constexpr CompModes CompilationMode()
    {
#ifdef NDEBUG
        return ReleaseMode;
#else
        return DebugMode;
#endif
    }

    template<typename T> struct ston_unsupported { static constexpr bool value = false; };

    //! String to number, forwarding to std::sto*; the std functions' exceptions (invalid_argument, out_of_range) pass through.
    template<typename T>
    T ston([[maybe_unused]] const std::string &str, [[maybe_unused]] size_t *idx = nullptr)
    {
        static_assert(ston_unsupported<T>::value, "rtl::ston: no conversion for this type.");
        return T{};
    }

    template<> inline double ston<double>(const std::string &str, size_t *idx) { return std::stod(str, idx); }
    template<> inline float ston<float>(const std::string &str, size_t *idx) { return std::stof(str, idx); }
    template<> inline int ston<int>(const std::string &str, size_t *idx) { return std::stoi(str, idx); }
    template<> inline long ston<long>(const std::string &str, size_t *idx) { return std::stol(str, idx); }
    template<> inline long double ston<long double>(const std::string &str, size_t *idx) { return std::stold(str, idx); }
    template<> inline long long ston<long long>(const std::string &str, size_t *idx) { return std::stoll(str, idx); }
    template<> inline unsigned long ston<unsigned long>(const std::string &str, size_t *idx) { return std::stoul(str, idx); }
    template<> inline unsigned long long ston<unsigned long long>(const std::string &str, size_t *idx) { return std::stoull(str, idx); }
}
