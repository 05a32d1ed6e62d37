"""uv_unwrap.unwrap_scene(): several meshes in one atlas, measured on the UVs it returns (all meshes of a
page together): UVs in [0,1], no flipped triangle, no texel covered twice, the same texel density for
every mesh, pages when the density asked for does not fit one; with stacking_tolerance, rigid copies of a
mesh take its texels (its UVs, not packed again) while a mirror image and a scaled copy get their own."""
import numpy as np
import pytest

import uv_unwrap
from conftest import corner_uvs, signed_areas, spherical_cap


def scene():
    """Five caps of different sizes (0.6 to 1.2 times the unit sphere's), apart."""
    V, F = spherical_cap(rings=8, segments=24)
    return [((0.6 + 0.15 * k) * V + 3.0 * k, F.copy()) for k in range(5)]


def area_3d(V, F):
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()


def doubly_covered(triangles, n=512):
    """Centres of an n x n raster of [0,1]^2 strictly inside two or more of the (t, 3, 2) triangles."""
    count = np.zeros((n, n), dtype=np.int32)
    for t in triangles:
        lo = np.clip(np.floor(t.min(axis=0) * n).astype(int), 0, n - 1)
        hi = np.clip(np.ceil(t.max(axis=0) * n).astype(int), 0, n - 1)
        xs, ys = np.meshgrid(np.arange(lo[0], hi[0] + 1), np.arange(lo[1], hi[1] + 1), indexing="ij")
        p = np.stack([(xs + 0.5) / n, (ys + 0.5) / n], axis=-1)
        inside = np.ones(xs.shape, dtype=bool)
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            inside &= (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - a[0]) > 0
        count[xs[inside], ys[inside]] += 1
    return int((count > 1).sum())


def check_pages(meshes, results, texture_size):
    tpu = results[0].stats["atlas"]["texels_per_unit"]
    pages = results[0].stats["atlas"]["page_count"]
    for (V, F), r in zip(meshes, results):
        assert 0 <= r.page < pages
        assert r.uv.min() >= 0 and r.uv.max() <= 1
        assert (signed_areas(r) > 0).all()
        density = texture_size * np.sqrt(np.abs(signed_areas(r)).sum() / area_3d(V, F))
        assert density == pytest.approx(tpu, rel=0.01)
    for page in range(pages):
        on_page = [corner_uvs(r) for r in results if r.page == page]
        assert on_page, "page %d holds no mesh" % page
        assert doubly_covered(np.concatenate(on_page)) == 0
        measures = results[0].stats["atlas"]["page_measures"][page]
        assert measures["flipped_faces"] == 0 and measures["border_crossings"] == 0
        assert measures["overlap_area"] == 0
    return tpu, pages


def test_one_atlas_for_all():
    meshes = scene()
    results = uv_unwrap.unwrap_scene(meshes, texture_size=256, padding=2)
    assert len(results) == 5
    tpu, pages = check_pages(meshes, results, 256)
    assert pages == 1 and tpu > 0
    # the same charts as unwrap() gives each mesh alone: only moved
    alone = uv_unwrap.unwrap(*meshes[0], texture_size=256, padding=2)
    assert results[0].stats["charts"] == alone.stats["charts"]
    assert np.array_equal(results[0].seams, alone.seams)


def test_pages_when_one_is_not_enough():
    meshes = scene()
    one = uv_unwrap.unwrap_scene(meshes, texture_size=256)[0].stats["atlas"]["texels_per_unit"]
    results = uv_unwrap.unwrap_scene(meshes, texture_size=256, texels_per_unit=1.3 * one)
    tpu, pages = check_pages(meshes, results, 256)
    assert pages >= 2
    assert tpu == pytest.approx(1.3 * one, rel=1e-9)


def test_a_mesh_too_large_for_a_page():
    with pytest.raises(uv_unwrap.UnwrapError) as e:
        uv_unwrap.unwrap_scene(scene(), texture_size=64, texels_per_unit=1e4)
    assert e.value.name == "ERROR_WRONG_PARAMETER"


def test_bad_scenes():
    V, F = spherical_cap(rings=4, segments=8)
    with pytest.raises(ValueError, match="empty"):
        uv_unwrap.unwrap_scene([])
    with pytest.raises(TypeError, match=r"meshes\[1\] must be a \(V, F\) pair"):
        uv_unwrap.unwrap_scene([(V, F), V])
    with pytest.raises(IndexError, match=r"meshes\[0\]: F\[0, 0\]"):
        uv_unwrap.unwrap_scene([(V, F + len(V))])
    with pytest.raises(ValueError, match="one entry per mesh"):
        uv_unwrap.unwrap_scene([(V, F)], seams=[None, None])
    with pytest.raises(ValueError, match="unwrap_scene"):
        uv_unwrap.unwrap(V, F, texels_per_unit=10.0)


def rotation(k):
    """A rotation (determinant +1) about an axis that changes with k."""
    axis = np.array([1.0, 0.3 * k, -0.2 * k + 0.5])
    axis /= np.linalg.norm(axis)
    a = 0.7 * k + 0.2
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K


def test_stacked_copies_share_the_texels_of_one():
    V, F = spherical_cap(rings=8, segments=24)
    copies = [(V @ rotation(k).T + [4.0 * k, 1.0, -2.0], F.copy()) for k in range(10)]
    mirror = (V * [-1.0, 1.0, 1.0] + [0.0, 9.0, 0.0], F.copy())  # a mirror image: never a copy
    larger = (1.5 * V + [0.0, -9.0, 0.0], F.copy())              # not rigid: its own texels
    meshes = copies + [mirror, larger]
    results = uv_unwrap.unwrap_scene(meshes, texture_size=256, padding=2, stacking_tolerance=1e-4)
    atlas = results[0].stats["atlas"]
    assert atlas["stacked_on"] == [None]
    for r in results[1:10]:
        assert r.stats["atlas"]["stacked_on"] == ["meshes[0]"]
        assert np.array_equal(corner_uvs(r), corner_uvs(results[0]))  # the same texels
        assert np.array_equal(r.seams, results[0].seams)
        assert r.page == results[0].page
    assert results[10].stats["atlas"]["stacked_on"] == [None] and results[11].stats["atlas"]["stacked_on"] == [None]
    charts = [r.stats["charts"] for r in results]
    assert atlas["charts_packed"] == charts[0] + charts[10] + charts[11]  # the copies' charts not packed again
    # valid on the meshes with texels of their own; every mesh at the density
    tpu = atlas["texels_per_unit"]
    for (Vm, Fm), r in zip(meshes, results):
        assert r.uv.min() >= 0 and r.uv.max() <= 1
        assert (signed_areas(r) > 0).all()
        assert 256 * np.sqrt(np.abs(signed_areas(r)).sum() / area_3d(Vm, Fm)) == pytest.approx(tpu, rel=0.01)
    own = [corner_uvs(results[i]) for i in (0, 10, 11)]
    assert doubly_covered(np.concatenate(own)) == 0
    measures = atlas["page_measures"][0]
    assert measures["flipped_faces"] == 0 and measures["border_crossings"] == 0 and measures["overlap_area"] == 0
    # without the option every copy is packed: a lower density
    plain = uv_unwrap.unwrap_scene(meshes, texture_size=256, padding=2)
    assert plain[0].stats["atlas"]["charts_packed"] == sum(charts)
    assert plain[0].stats["atlas"]["texels_per_unit"] < tpu
    with pytest.raises(ValueError, match="unwrap_scene"):
        uv_unwrap.unwrap(V, F, stacking_tolerance=1e-4)

