// Optional step-by-step observation of an algorithm, at zero cost when unused.
//
// An algorithm that can be traced takes an observer type as its last template parameter, defaulting to NoTrace,
// and is given an observer object with setObserver(Observer *). It reports each step it takes as an event
// (a small struct of plain numbers, defined next to the algorithm) and guards every report with
//     if constexpr (Observer::enabled) if (observer_) (*observer_)(Event{...});
// so that with NoTrace the event is never built and the untraced code is exactly the code without tracing.
//
// Every event type names itself and lists its fields, so that one generic converter (the wasm binding, a printer,
// a test) handles all of them:
//     struct Compare {
//         static constexpr const char *kind = "compare";
//         size_t i, j; double distance, threshold; bool linked;
//         template<class F> void fields(F &&f) const { f("i", i); f("j", j); f("distance", distance);
//                                                      f("threshold", threshold); f("linked", linked); }
//     };
// Field values are integers, floating-point numbers or bools. A trace replayed from its first event to its last
// ends in the state the algorithm returns.
//
// TraceLog<Events...> records every event in order, as a std::variant, for tests, teaching tools and bindings.
#pragma once

#include <cstddef>
#include <variant>
#include <vector>

namespace rtl
{
    //! The default observer: disabled, so traced algorithms compile their reports away.
    struct NoTrace
    {
        static constexpr bool enabled = false;
        template<class Event> void operator()(const Event &) const noexcept {}
    };

    //! Records every event it is given, in order.
    template<class... Events>
    struct TraceLog
    {
        static constexpr bool enabled = true;
        typedef std::variant<Events...> EventType;

        std::vector<EventType> events;

        template<class Event> void operator()(const Event &e) { events.emplace_back(e); }
        void clear() { events.clear(); }
        [[nodiscard]] size_t size() const { return events.size(); }
    };
}
