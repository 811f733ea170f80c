// A PDF report of a laser scan: the scan with its clusters in colours and fitted line segments, the same scene
// lifted into 3D, and a table of segment statistics.
//
//   e_report [carmen.log [scan index [output folder]]]
//
// Defaults: the intel.log excerpt, scan 26, folder ./e_report_output (the report is e_report_output/scan_report.pdf).
// Without pdflatex the program still succeeds: LaTeXDoc says so and keeps the LaTeX sources.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "rtl/Vectorization.h"
#include "rtl/io/CarmenLog.h"
#include "rtl/io/LaTeXDoc.h"
#include "rtl/seg/CAR_Segmenter.h"

namespace
{
    struct Segment
    {
        rtl::Vector2f beg, end;
        size_t points;
        double rms;
    };

    std::string fixed(double v, int digits)
    {
        char buf[64];
        std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
        return buf;
    }
}

int main(int argc, char **argv)
{
    try
    {
        std::string log = argc > 1 ? argv[1] : std::string(RTL_EXAMPLE_DATA_DIR) + "/intel.log";
        size_t index = argc > 2 ? static_cast<size_t>(std::stoul(argv[2])) : 26;
        std::string out_dir = argc > 3 ? argv[3] : "e_report_output";

        auto scans = rtl::readCarmenLogFile<float>(log);
        if (scans.empty())
        {
            std::cerr << "e_report: no FLASER scan in " << log << "\n";
            return 1;
        }
        index = std::min(index, scans.size() - 1);
        const auto &scan = scans[index];

        // Clusters (CAR segmenter) and their line segments (incremental TLS vectorizer, sigma 3 cm).
        rtl::CAR_Segmenter<rtl::Vector2f> segmenter(2, 0.1f, 0.5f);
        segmenter.loadData(scan.points);
        std::vector<std::vector<rtl::Vector2f>> clusters;
        while (segmenter.clustersAvailable() > 0)
        {
            auto c = segmenter.grabCluster();
            if (c.size() >= 3)
                clusters.push_back(std::move(c));
        }
        std::vector<Segment> segments;
        std::vector<size_t> segment_cluster;
        rtl::VectorizerITLSProjections2D<float, double> vectorizer;
        vectorizer.setSigma(0.03f);
        for (size_t c = 0; c < clusters.size(); ++c)
        {
            if (!vectorizer(clusters[c]))
                continue;
            const auto &lines = vectorizer.lineSegments();
            const auto &idx = vectorizer.indices();
            const auto &approx = vectorizer.approximations();
            for (size_t i = 0; i < lines.size() && i < idx.size() && i < approx.size(); ++i)
            {
                segments.push_back({lines[i].beg(), lines[i].end(), idx[i].second - idx[i].first,
                                    std::sqrt(std::max(0.0, static_cast<double>(approx[i].errSquared())))});
                segment_cluster.push_back(c);
            }
        }

        // 2D figure: grid, axes, coloured clusters, black segments, the robot.
        rtl::LaTeXTikz2D fig;
        fig.setSize(12, 12);
        fig.setMarkRadius(0.04f);
        fig.addGridH("style={draw=gray!40, very thin}", 1);
        fig.addGridV("style={draw=gray!40, very thin}", 1);
        fig.addAxisX("style={draw=black}", "%.0f", rtl::LaTeXTikz2D::position_below, 2);
        fig.addAxisY("style={draw=black}", "%.0f", rtl::LaTeXTikz2D::position_left, 2);
        fig.addDescriptionX("x [m]");
        fig.addDescriptionY("y [m]");
        std::vector<std::string> colours;
        for (size_t c = 0; c < clusters.size(); ++c)
        {
            double hue = std::fmod(static_cast<double>(c) * 0.618033988749895, 1.0);
            colours.push_back(fig.saveColor("{hsb}{" + fixed(hue, 3) + ",0.9,0.85}"));
            fig.addPlot(clusters[c], "", "style={draw=" + colours.back() + ",fill=" + colours.back() + "}",
                        rtl::LaTeXTikz2D::latex_mark_dot);
        }
        for (const auto &s : segments)
            fig.addLine(s.beg, s.end, "style={draw=black, line width=0.8pt}");
        fig.addPlot(std::vector<rtl::Vector2f>{{0, 0}}, "", "style={draw=black,fill=white}",
                    rtl::LaTeXTikz2D::latex_mark_robot, 2.0f);
        // Equal scales: the figure must not distort the map.
        float w = fig.maxX() - fig.minX(), h = fig.maxY() - fig.minY();
        fig.setSize(12, w > 0 ? std::clamp(12 * h / w, 2.0f, 20.0f) : 12);

        // 3D figure: every segment as a 1 m high wall, seen from above and behind the robot.
        rtl::LaTeXTikz3D walls;
        walls.setView(45, rtl::Vector3f(1, 0.3f, -0.8f));
        for (const auto &s : segments)
        {
            rtl::Vector2f d = s.end - s.beg;
            if (!(d.length() > 0))
                continue;
            rtl::Vector3f n(-d.y(), d.x(), 0);
            rtl::Polygon3Df wall(n, n.normalized().dot(rtl::Vector3f(s.beg.x(), s.beg.y(), 0)));
            wall.addPoint(rtl::Vector3f(s.beg.x(), s.beg.y(), 0));
            wall.addPoint(rtl::Vector3f(s.end.x(), s.end.y(), 0));
            wall.addPoint(rtl::Vector3f(s.end.x(), s.end.y(), 1));
            wall.addPoint(rtl::Vector3f(s.beg.x(), s.beg.y(), 1));
            walls.addFace(wall, "style={fill=blue!25}", "style={fill=orange!30}", "style={draw=black}");
        }
        walls.addMark(rtl::Vector3f(0, 0, 0), "style={draw=black,fill=red}", rtl::LaTeXTikz3D::latex_mark_dot);

        // Table of segment statistics.
        rtl::LaTeXTable table;
        table.setColumnStyle("r|r|r|r|r");
        table.setHeading({"segment", "cluster", "points", "length [m]", "rms [mm]"});
        table.addHLine();
        for (size_t i = 0; i < segments.size(); ++i)
            table.addRow({std::to_string(i), std::to_string(segment_cluster[i]), std::to_string(segments[i].points),
                          fixed((segments[i].end - segments[i].beg).length(), 2), fixed(1000 * segments[i].rms, 1)});

        bool ok;
        {
            rtl::LaTeXDoc doc(out_dir, "scan_report");
            doc.setEscapeCaptions(true);   // the captions are plain text (the log's path may hold '_' or '%')
            doc.setStopOnFailure(true);    // without a PDF, keep the LaTeX sources (RTL's default removes them)
            doc.addLE(fig, "Scan " + std::to_string(index) + " of " + log + ": " + std::to_string(clusters.size()) +
                                   " clusters (colours) and " + std::to_string(segments.size()) + " segments (black)");
            doc.addLE(walls, "The segments as 1 m walls");
            doc.addTable(table, "Segment statistics");
            ok = doc.finish();
            std::cout << "scan " << index << ": " << scan.points.size() << " beams, " << clusters.size()
                      << " clusters, " << segments.size() << " segments\n";
            if (ok)
                std::cout << "report: " << doc.pdfPath() << "\n";
            else
                std::cout << "no PDF (see the message above); LaTeX sources in " << doc.tmpDir() << "\n";
        }
        return 0;
    }
    catch (const std::exception &e)
    {
        std::cerr << "e_report: " << e.what() << "\n";
        return 1;
    }
}
