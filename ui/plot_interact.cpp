// The plot widget's interaction: pan and zoom, legend clicks, the hover readout, the context
// menu and the CSV export of what is visible.
#include "ui/plot_internal.hpp"

#include <charconv>

namespace pl::ui::plot::detail {

namespace {

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"') out += '"';
        out += ch;
    }
    return out + "\"";
}

}  // namespace

std::string visible_csv(const Context& c, double x0, double x1, bool log) {
    if (log) {
        x0 = std::pow(10.0, x0);
        x1 = std::pow(10.0, x1);
    }
    std::string out = "series," + csv_field(c.x_label) + "," + csv_field(c.y_label) + "\n";
    // Shortest form that reads back to the same double.
    auto append = [&out](double v) {
        char buf[32];
        const auto r = std::to_chars(buf, buf + sizeof buf, v);
        out.append(buf, r.ptr);
    };
    for (const Item& item : c.items) {
        if (!item_visible(item) || !item.ys || (item.kind != ItemKind::line && item.kind != ItemKind::markers)) continue;
        const std::string name = csv_field(item.legend);
        for (int i = 0; i < item.count; ++i) {
            if (item.xs[i] < x0 || item.xs[i] > x1) continue;
            out += name;
            out += ',';
            append(item.xs[i]);
            out += ',';
            append(item.ys[i]);
            out += '\n';
        }
    }
    return out;
}

// The sample closest to the mouse (in pixels) among the visible lines and markers.
Nearest find_nearest(const std::vector<Item>& items, const Frame& f, ImVec2 mouse, bool sorted) {
    Nearest best;
    auto consider = [&](const Item& item, int i) {
        const double* xs = plot_xs(item);
        const double* ys = plot_ys(item);
        if (!std::isfinite(xs[i]) || !std::isfinite(ys[i])) return;
        const ImVec2 p{f.px(xs[i]), f.py(ys[i])};
        const float d = std::hypot(p.x - mouse.x, p.y - mouse.y);
        if (d < best.distance) best = {&item, item.xs[i], item.ys[i], p, d};
    };
    const double mx = f.data_x(mouse.x);
    const double pixel = (f.x1 - f.x0) / std::max(1.0f, f.max.x - f.min.x);
    for (const Item& item : items) {
        if (!item_visible(item) || !item.ys || item.count <= 0) continue;
        if (item.kind != ItemKind::line && item.kind != ItemKind::markers) continue;
        const double* xs = plot_xs(item);
        if (!sorted || item.kind != ItemKind::line) {
            for (int i = 0; i < item.count; ++i) consider(item, i);
            continue;
        }
        // Samples within a few pixels of the mouse column (bounded, so 100k points stay cheap).
        const int lo = static_cast<int>(std::lower_bound(xs, xs + item.count, mx - 8 * pixel) - xs);
        const int hi = static_cast<int>(std::upper_bound(xs, xs + item.count, mx + 8 * pixel) - xs);
        const int step = std::max(1, (hi - lo) / 256);
        for (int i = std::max(0, lo - 1); i < std::min(item.count, hi + 1); i += step) consider(item, i);
    }
    return best;
}


const LegendEntry* interact(Context& c, const Frame& f, const std::vector<LegendEntry>& entries, bool legend_outside,
                            bool fit_all, PlotResult& result) {
    ImGuiIO& io = ImGui::GetIO();
    PlotState& st = *c.state;
    TimeAxisLink& link = *c.x;
    const double x0 = f.x0, x1 = f.x1, y0 = f.y0, y1 = f.y1;
    ImGui::SetCursorScreenPos(f.min);
    ImGui::InvisibleButton("##area", {std::max(1.0f, f.max.x - f.min.x), std::max(1.0f, f.max.y - f.min.y)},
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    result.hovered = hovered;
    const ImVec2 mouse = io.MousePos;
    const LegendEntry* over_entry = nullptr;
    for (const LegendEntry& e : entries)
        if (mouse.x >= e.min.x && mouse.x < e.max.x && mouse.y >= e.min.y && mouse.y < e.max.y) over_entry = &e;
    const bool legend_clickable = hovered || (legend_outside && ImGui::IsWindowHovered());
    if (legend_clickable && over_entry && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        if (c.hidden->erase(over_entry->label) == 0) c.hidden->insert(over_entry->label);
    } else if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        link.follow_latest = true;
        st.auto_fit_y = true;
    } else if (!fit_all && active && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && !over_entry) {
        const double dx = io.MouseDelta.x * (x1 - x0) / (f.max.x - f.min.x);
        if (dx != 0.0) {
            link.follow_latest = false;
            link.x_min -= dx;
            link.x_max -= dx;
        }
        if (!st.auto_fit_y) {
            const double dy = io.MouseDelta.y * (y1 - y0) / (f.max.y - f.min.y);
            st.y_min += dy;
            st.y_max += dy;
        }
    }
    if (!fit_all && hovered && io.MouseWheel != 0.0f) {
        const double factor = std::pow(0.8, static_cast<double>(io.MouseWheel));
        if (io.KeyCtrl) {
            const double my = f.data_y(mouse.y);
            st.auto_fit_y = false;
            st.y_min = my + (y0 - my) * factor;
            st.y_max = my + (y1 - my) * factor;
        } else if (link.follow_latest) {
            link.window_s = std::clamp((link.window_s > 0.0 ? link.window_s : x1 - x0) * factor, 1e-3, 1e7);
        } else {
            const double mx = f.data_x(mouse.x);
            link.x_min = mx + (x0 - mx) * factor;
            link.x_max = mx + (x1 - mx) * factor;
        }
    }
    if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right) && ImGui::GetMouseDragDelta(ImGuiMouseButton_Right).x == 0.0f)
        ImGui::OpenPopup("##plot_menu");
    return over_entry;
}

// The nearest sample under the mouse, and the shared time cursor of linked plots.
void hover_readout(Context& c, const Frame& f, const LegendEntry* over_entry, bool fit_all, bool hovered,
                   const Style& s) {
    TimeAxisLink& link = *c.x;
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const bool readout = hovered && !has_flag(PlotFlags_NoHover);
    if (!fit_all) link.hover_x = readout ? f.data_x(mouse.x) : (link.hover_owner == c.id || has_flag(PlotFlags_NoHover) ? nan : link.hover_x);
    if (readout) link.hover_owner = c.id;
    if (!readout || over_entry || ImGui::IsMouseDragging(ImGuiMouseButton_Left)) return;
    const Nearest n = find_nearest(c.items, f, mouse, !fit_all);
    if (!n.item || n.distance >= 60.0f) return;
    ImGui::GetWindowDrawList()->AddCircle(n.at, 5.0f, s.text, 12, 1.5f);
    ImGui::BeginTooltip();
    if (!n.item->legend.empty()) ImGui::TextUnformatted(n.item->legend.c_str());
    ImGui::Text("%s: %.6g", c.x_label.empty() ? "x" : c.x_label.c_str(), n.x);
    ImGui::Text("%s: %.6g", c.y_label.empty() ? "y" : c.y_label.c_str(), n.y);
    if (n.item->detail) {
        ImGui::Separator();
        ImGui::TextUnformatted(n.item->detail(n.x).c_str());
    }
    ImGui::EndTooltip();
}

void context_menu(Context& c, bool fit_all, PlotResult& result) {
    if (!ImGui::BeginPopup("##plot_menu")) return;
    TimeAxisLink& link = *c.x;
    if (!fit_all) {
        ImGui::MenuItem("Follow latest", nullptr, &link.follow_latest);
        ImGui::MenuItem("Auto-fit y", nullptr, &c.state->auto_fit_y);
        if (ImGui::MenuItem("Show all data")) {
            link.follow_latest = true;
            link.window_s = 0.0;
            c.state->auto_fit_y = true;
        }
        ImGui::Separator();
    }
    if (ImGui::MenuItem("Export visible data to CSV")) result.export_csv = true;
    if (ImGui::MenuItem("Export plot to PNG")) result.export_png = true;
    ImGui::EndPopup();
}

}  // namespace pl::ui::plot::detail
