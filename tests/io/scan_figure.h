// Test helper: a figure of a real CARMEN scan with its clusters in colours and fitted line segments.
// Clusters come from rtl::CAR_Segmenter and segments from rtl::VectorizerITLSProjections2D, as in the RTL paper.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/io/LaTeXTable.h"
#include "rtl/io/LaTeXTikz2D.h"
#include "rtl/seg/CAR_Segmenter.h"

namespace rtl_test_latex
{
    struct Segment
    {
        rtl::Vector2f beg, end;
        size_t points;
        double rms;   // residual of the TLS fit (m)
    };

    //! Clusters of the library's CAR segmenter (step 2, distance bounds 0.1 .. 0.5 m); at least 3 points each.
    inline std::vector<std::vector<rtl::Vector2f>> clusters(const std::vector<rtl::Vector2f> &pts)
    {
        rtl::CAR_Segmenter<rtl::Vector2f> seg(2, 0.1f, 0.5f);
        seg.loadData(pts);
        std::vector<std::vector<rtl::Vector2f>> out;
        while (seg.clustersAvailable() > 0)
        {
            auto c = seg.grabCluster();
            if (c.size() >= 3)
                out.push_back(std::move(c));
        }
        return out;
    }

    //! Line segments of one cluster from the library's incremental TLS vectorizer (sigma 3 cm).
    inline void vectorize(const std::vector<rtl::Vector2f> &pts, std::vector<Segment> &out)
    {
        rtl::VectorizerITLSProjections2D<float, double> vectorizer;
        vectorizer.setSigma(0.03f);
        if (!vectorizer(pts))
            return;
        const auto &segs = vectorizer.lineSegments();
        const auto &idx = vectorizer.indices();
        const auto &approx = vectorizer.approximations();
        for (size_t i = 0; i < segs.size() && i < idx.size() && i < approx.size(); ++i)
            out.push_back({segs[i].beg(), segs[i].end(), idx[i].second - idx[i].first,
                           std::sqrt(std::max(0.0, static_cast<double>(approx[i].errSquared())))});
    }

    struct ScanResult
    {
        std::vector<rtl::Vector2f> points;
        std::vector<std::vector<rtl::Vector2f>> clusters;
        std::vector<Segment> segments;
    };

    inline ScanResult process(const rtl::CarmenScan<float> &scan)
    {
        ScanResult r;
        r.points = scan.points;
        r.clusters = clusters(scan.points);
        for (const auto &c : r.clusters)
            vectorize(c, r.segments);
        return r;
    }

    //! The RTL-paper style figure: grey grid and axes in metres, each cluster's points as dots in its own colour,
    //! the fitted segments as thick black lines, the robot at the origin.
    inline void drawScan(rtl::LaTeXTikz2D &le, const ScanResult &r, const std::string &caption_x = "x [m]",
                         const std::string &caption_y = "y [m]")
    {
        // Equal scales in x and y (a map must not be distorted): 12 cm wide, height from the aspect ratio.
        float min_x = 0, max_x = 0, min_y = 0, max_y = 0;   // the robot at the origin is in the picture
        for (const auto &p : r.points)
            if (std::isfinite(p.x()) && std::isfinite(p.y()))
            {
                min_x = std::min(min_x, p.x());
                max_x = std::max(max_x, p.x());
                min_y = std::min(min_y, p.y());
                max_y = std::max(max_y, p.y());
            }
        float w = 12.0f, h = max_x > min_x ? w * (max_y - min_y) / (max_x - min_x) : w;
        le.setSize(w, std::clamp(h, 1.0f, 30.0f));
        le.setMarkRadius(0.04f);
        le.addGridH("style={draw=gray!40, very thin}", 1);
        le.addGridV("style={draw=gray!40, very thin}", 1);
        le.addAxisX("style={draw=black}", "%.0f", rtl::LaTeXTikz2D::position_below, 2);
        le.addAxisY("style={draw=black}", "%.0f", rtl::LaTeXTikz2D::position_left, 2);
        le.addDescriptionX(caption_x);
        le.addDescriptionY(caption_y);
        for (size_t i = 0; i < r.clusters.size(); ++i)
        {
            // Hues spread by the golden angle so that neighbouring clusters differ.
            double hue = std::fmod(static_cast<double>(i) * 0.618033988749895, 1.0);
            std::string c = le.saveColor("{hsb}{" + std::to_string(hue) + ",0.9,0.85}");
            le.addPlot(r.clusters[i], "", "style={draw=" + c + ",fill=" + c + "}", rtl::LaTeXTikz2D::latex_mark_dot);
        }
        for (const auto &s : r.segments)
            le.addLine(s.beg, s.end, "style={draw=black, line width=0.8pt}");
        le.addPlot(std::vector<rtl::Vector2f>{{0, 0}}, "", "style={draw=black,fill=white}",
                   rtl::LaTeXTikz2D::latex_mark_robot, 2.0f);
    }
}
