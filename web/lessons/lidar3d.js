// The LiDAR data in 3D: the page3d panel (web/view3d/mount-lidar3d.js) in the lesson frame. It has no trace: the
// panel recomputes with the package when its own settings change.
import { mountLidar3D } from '../view3d/mount-lidar3d.js';

export default {
  id: 'lidar-3d',
  menu: '3D LiDAR',
  title: 'The LiDAR scan in 3D',
  summary: 'Ouster rings segmented and vectorized in 3D by the package: orbit the view, compare it with the top view.',
  noFigure: true,
  async create(host) {
    // A user's organised cloud (an opened PCD) replaces the bundled Ouster scan.
    const d = host.source && host.data.DATASETS[host.source.dataset];
    const cloud = d?.cloud ? await host.data.loadCloud(host.source.dataset) : undefined;
    const panel = await mountLidar3D(host.stage, host.rtl, cloud ? { cloud, label: d.label } : {});
    host.text.textContent = 'Each ring (one laser beam over a full turn) is segmented like a 2D scan; clusters are vectorized into 3D line segments, and patches of neighbouring rings are fitted with planes.';
    return {
      recompute: () => ({ steps: 0 }),
      show() {},
      finalState: () => ({ method: 'lidar-3d', settings: panel.settings?.() ?? null }),
      dispose: () => panel.dispose?.(),
    };
  },
};
