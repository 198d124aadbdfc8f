<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>inlay::studio::Autosaver</name>
    <message>
        <location filename="../app/studio/autosave.cpp" line="60"/>
        <source>%1: cannot take the lock</source>
        <translation>%1: die Sperre lässt sich nicht setzen</translation>
    </message>
    <message>
        <location filename="../app/studio/autosave.cpp" line="102"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1: kann nicht geschrieben werden (%2)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Document</name>
    <message>
        <location filename="../app/studio/document.cpp" line="307"/>
        <location filename="../app/studio/document.cpp" line="337"/>
        <source>Preparation was cancelled.</source>
        <translation>Die Vorbereitung wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="511"/>
        <source>There is no object %1.</source>
        <translation>Es gibt kein Objekt %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="513"/>
        <source>The scene is still being prepared.</source>
        <translation>Die Szene wird noch vorbereitet.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="514"/>
        <source>The scene could not be prepared.</source>
        <translation>Die Szene konnte nicht vorbereitet werden.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="393"/>
        <location filename="../app/studio/document.cpp" line="827"/>
        <location filename="../app/studio/document.cpp" line="1015"/>
        <location filename="../app/studio/document.cpp" line="1074"/>
        <source>The position is not a number.</source>
        <translation>Die Position ist keine Zahl.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="395"/>
        <location filename="../app/studio/document.cpp" line="525"/>
        <location filename="../app/studio/document.cpp" line="542"/>
        <source>The height must be greater than zero.</source>
        <translation>Die Höhe muss größer als null sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="417"/>
        <location filename="../app/studio/document.cpp" line="451"/>
        <source>Move object %1</source>
        <translation>Objekt %1 verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="425"/>
        <source>Change height of object %1</source>
        <translation>Höhe von Objekt %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="431"/>
        <location filename="../app/studio/document.cpp" line="444"/>
        <source>The turn is not a number.</source>
        <translation>Die Drehung ist keine Zahl.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="437"/>
        <source>Turn object %1</source>
        <translation>Objekt %1 drehen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="496"/>
        <source>Change material of object %1</source>
        <translation>Material von Objekt %1 ändern</translation>
    </message>
    <message>
        <source>Insert object %1</source>
        <translation type="vanished">Objekt %1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="540"/>
        <source>The model has no triangles.</source>
        <translation>Das Modell hat keine Dreiecke.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="548"/>
        <source>object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="551"/>
        <source>Insert %1</source>
        <translation>%1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="569"/>
        <source>Duplicate %1</source>
        <translation>%1 duplizieren</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="619"/>
        <source>Rename %1</source>
        <translation>%1 umbenennen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="627"/>
        <source>Hide %1</source>
        <translation>%1 ausblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="627"/>
        <source>Show %1</source>
        <translation>%1 einblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="635"/>
        <location filename="../app/studio/document.cpp" line="652"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="636"/>
        <location filename="../app/studio/document.cpp" line="653"/>
        <source>cube</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="691"/>
        <source>Delete object %1</source>
        <translation>Objekt %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="791"/>
        <source>Open a photo first.</source>
        <translation>Öffnen Sie zuerst ein Foto.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="811"/>
        <source>There is no estimated box yet.</source>
        <translation>Es gibt noch keinen geschätzten Raum.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="817"/>
        <source>Accept the estimated box</source>
        <translation>Geschätzten Raum übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="823"/>
        <source>There is no such corner of the back wall.</source>
        <translation>Diese Ecke der Rückwand gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="834"/>
        <source>Move a corner of the back wall</source>
        <translation>Ecke der Rückwand verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="841"/>
        <source>Estimate the box again</source>
        <translation>Raum neu schätzen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="846"/>
        <source>A light&apos;s outline needs at least three points around an area.</source>
        <translation>Der Umriss einer Lampe braucht mindestens drei Punkte um eine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="855"/>
        <source>Outline light %1</source>
        <translation>Lampe %1 umreißen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="861"/>
        <location filename="../app/studio/document.cpp" line="1037"/>
        <source>Each box of a shaft must be at least two pixels wide and high.</source>
        <translation>Jeder Rahmen eines Sonnenstrahls muss mindestens zwei Pixel breit und hoch sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="870"/>
        <source>Add shaft %1</source>
        <translation>Sonnenstrahl %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="877"/>
        <source>A surface&apos;s outline needs at least three points around an area.</source>
        <translation>Der Umriss einer Fläche braucht mindestens drei Punkte um eine Fläche.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="887"/>
        <source>Add surface %1</source>
        <translation>Fläche %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="897"/>
        <source>An occluder needs a stroke over the thing in front and one over what is behind it.</source>
        <translation>Ein Verdecker braucht einen Strich über dem, was davor ist, und einen über dem, was dahinter ist.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="903"/>
        <source>Add occluder %1</source>
        <translation>Verdecker %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="909"/>
        <source>There is no such occluder, or the stroke is empty.</source>
        <translation>Diesen Verdecker gibt es nicht, oder der Strich ist leer.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="916"/>
        <source>Add a stroke to occluder %1</source>
        <translation>Strich zu Verdecker %1 hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="927"/>
        <source>There is no such mark.</source>
        <translation>Diese Markierung gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="935"/>
        <source>Delete light %1</source>
        <translation>Lampe %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="936"/>
        <source>Delete shaft %1</source>
        <translation>Sonnenstrahl %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="937"/>
        <source>Delete surface %1</source>
        <translation>Fläche %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="938"/>
        <source>Delete occluder %1</source>
        <translation>Verdecker %1 löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1018"/>
        <source>There is no such point.</source>
        <translation>Diesen Punkt gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1027"/>
        <location filename="../app/studio/document.cpp" line="1046"/>
        <source>The outline would lose its area.</source>
        <translation>Der Umriss würde seine Fläche verlieren.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1028"/>
        <source>Reshape light %1</source>
        <translation>Licht %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1038"/>
        <source>Reshape shaft %1</source>
        <translation>Lichtschacht %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1047"/>
        <source>Reshape surface %1</source>
        <translation>Fläche %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1055"/>
        <source>Reshape occluder %1</source>
        <translation>Verdecker %1 umformen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1071"/>
        <source>There is no such axis.</source>
        <translation>Diese Achse gibt es nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1076"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Jede Linie muss mindestens zwei Pixel lang sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1082"/>
        <source>The two lines lie on one line: draw two different edges.</source>
        <translation>Die beiden Linien liegen auf einer Geraden: Zeichnen Sie zwei verschiedene Kanten.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1091"/>
        <source>Draw the %1 vanishing lines</source>
        <translation>Fluchtlinien für %1 zeichnen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1092"/>
        <source>Forget the %1 vanishing lines</source>
        <translation>Fluchtlinien für %1 verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1106"/>
        <source>The room has no surface %1.</source>
        <translation>Der Raum hat keine Fläche %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1109"/>
        <source>Unknown material.</source>
        <translation>Unbekanntes Material.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1112"/>
        <source>The roughness must lie between 0 and 1.</source>
        <translation>Die Rauheit muss zwischen 0 und 1 liegen.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1118"/>
        <source>Change the material of %1</source>
        <translation>Material von %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1126"/>
        <source>Change the camera response</source>
        <translation>Kamerakennlinie ändern</translation>
    </message>
</context>
<context>
    <name>inlay::studio::EngineText</name>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="33"/>
        <source>empty file</source>
        <translation>leere Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="34"/>
        <source>cannot open for reading</source>
        <translation>kann nicht zum Lesen geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="35"/>
        <source>read failed</source>
        <translation>Lesen fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="36"/>
        <source>no triangles</source>
        <translation>keine Dreiecke</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="37"/>
        <source>import failed: %1</source>
        <translation>Import fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="38"/>
        <source>non-finite coordinate &apos;%1&apos;</source>
        <translation>nicht endliche Koordinate „%1“</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="39"/>
        <source>non-finite coordinate</source>
        <translation>nicht endliche Koordinate</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="40"/>
        <source>malformed number &apos;%1&apos;</source>
        <translation>fehlerhafte Zahl „%1“</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="41"/>
        <source>malformed face index &apos;%1&apos;</source>
        <translation>fehlerhafter Flächenindex „%1“</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="42"/>
        <source>face corner without a vertex index</source>
        <translation>Flächenecke ohne Eckpunktindex</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="43"/>
        <source>face index 0 (OBJ indices start at 1)</source>
        <translation>Flächenindex 0 (OBJ-Indizes beginnen bei 1)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="44"/>
        <source>a face needs at least 3 vertices</source>
        <translation>eine Fläche braucht mindestens 3 Eckpunkte</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="45"/>
        <source>more than %1 triangles</source>
        <translation>mehr als %1 Dreiecke</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="46"/>
        <source>more than %1 vertices</source>
        <translation>mehr als %1 Eckpunkte</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="47"/>
        <source>%1 vertices exceed the limit of %2</source>
        <translation>%1 Eckpunkte überschreiten die Grenze von %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="48"/>
        <source>&apos;%1&apos; needs %2 numbers</source>
        <translation>„%1“ braucht %2 Zahlen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="49"/>
        <source>not a PLY file (missing &apos;ply&apos; magic)</source>
        <translation>keine PLY-Datei (die Kennung „ply“ fehlt)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="50"/>
        <source>not a GLB file</source>
        <translation>keine GLB-Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="51"/>
        <source>invalid glTF JSON</source>
        <translation>ungültiges glTF-JSON</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="52"/>
        <source>buffer file not found: %1</source>
        <translation>Pufferdatei nicht gefunden: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="54"/>
        <source>none given; the objects are lit by the room&apos;s gathered light only</source>
        <translation>keine angegeben; die Objekte werden nur vom gesammelten Licht des Raums beleuchtet</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="56"/>
        <source>ignored, the photo is already linear (EXR/HDR)</source>
        <translation>ignoriert, das Foto ist bereits linear (EXR/HDR)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="57"/>
        <source>the estimated back wall is unusable (%1); using a 5 x 5.5 m room: give layout.back_wall_px</source>
        <translation>die geschätzte Rückwand ist unbrauchbar (%1); ein Raum von 5 x 5,5 m wird verwendet: layout.back_wall_px angeben</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="60"/>
        <source>the photo shows no clear room structure; the camera is a fallback (prior focal length, upright): give camera.vanishing_points_px for a reliable result</source>
        <translation>das Foto zeigt keine klare Raumstruktur; die Kamera ist eine Notlösung (Brennweite aus der Annahme, aufrecht): für ein verlässliches Ergebnis camera.vanishing_points_px angeben</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="64"/>
        <source>the photo shows no clear room structure; the camera is a fallback (default focal length, upright): give camera.vanishing_points_px for a reliable result</source>
        <translation>das Foto zeigt keine klare Raumstruktur; die Kamera ist eine Notlösung (Standardbrennweite, aufrecht): für ein verlässliches Ergebnis camera.vanishing_points_px angeben</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="68"/>
        <source>strength kept as estimated: %1</source>
        <translation>Stärke wie geschätzt beibehalten: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="69"/>
        <source>the window the sun comes through is out of view; its sky is a light of %1 x %2 m on the %3 (where the beam came from), its intensity fitted (give source_box_px, or outline the window as a light, to choose)</source>
        <translation>das Fenster, durch das die Sonne scheint, ist nicht im Bild; sein Himmel ist ein Licht von %1 x %2 m auf %3 (woher der Strahl kam), seine Stärke angepasst (zur Wahl source_box_px angeben oder das Fenster als Licht umranden)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="73"/>
        <source>%1&apos;s matte shows the floor under the top at %2 of %3 points, so it is a slab %4 m thick (give thickness_m to choose; 0: solid)</source>
        <translation>die Maske von %1 zeigt an %2 von %3 Punkten den Boden unter der Platte, also ist sie eine %4 m dicke Platte (zur Wahl thickness_m angeben; 0: massiv)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="77"/>
        <source>gathered light still changed by %1% in the last of %2 passes (the walls the camera does not see are uncertain)</source>
        <translation>das gesammelte Licht änderte sich im letzten von %2 Durchgängen noch um %1 % (die Wände, die die Kamera nicht sieht, sind unsicher)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="80"/>
        <source>lights %1 are out of view: they share one radiance (the photo shows only their sum)</source>
        <translation>die Lichter %1 sind nicht im Bild: sie teilen sich eine Strahldichte (das Foto zeigt nur ihre Summe)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="83"/>
        <source>the ceiling the camera does not see: the light fit&apos;s model of the room gives it %1 grey, not the seen walls&apos; mean (%2; a sunlit patch lights the ceiling straight on, and the photo does not show its albedo)</source>
        <translation>die Decke, die die Kamera nicht sieht: das Modell des Raums in der Lichtanpassung gibt ihr %1 Grau, nicht den Mittelwert der sichtbaren Wände (%2; ein sonnenbeschienener Fleck beleuchtet die Decke direkt, und das Foto zeigt ihre Albedo nicht)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="87"/>
        <source>outside the room; moved %1 m to fit inside it</source>
        <translation>außerhalb des Raums; um %1 m verschoben, damit es hineinpasst</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="88"/>
        <source>larger than the room in every direction; its position is kept</source>
        <translation>in jeder Richtung größer als der Raum; seine Position wird beibehalten</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="90"/>
        <source>%1 lights none of the room the photo shows: its intensity stays at its start</source>
        <translation>%1 beleuchtet nichts vom Raum, den das Foto zeigt: seine Stärke bleibt beim Startwert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="92"/>
        <source>the photo&apos;s direct light is black: the lights are fitted to darkness</source>
        <translation>das direkte Licht des Fotos ist schwarz: die Lichter werden an Dunkelheit angepasst</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="94"/>
        <source>light refinement failed (%1): the start is kept</source>
        <translation>Verfeinerung der Lichter fehlgeschlagen (%1): der Startwert bleibt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="97"/>
        <source>not converged: stopped by %1 after %2 iterations (%3 s): primal residual %4, dual %5, tolerance %6</source>
        <translation>nicht konvergiert: angehalten durch %1 nach %2 Iterationen (%3 s): primales Residuum %4, duales %5, Toleranz %6</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="100"/>
        <source>the iteration cap</source>
        <translation>die Iterationsgrenze</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="101"/>
        <source>non-finite residuals</source>
        <translation>nicht endliche Residuen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="102"/>
        <source>cancellation</source>
        <translation>den Abbruch</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="106"/>
        <source>noise level</source>
        <translation>Rauschpegel</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="107"/>
        <source>edge</source>
        <translation>Kanten</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="108"/>
        <source>the fitted %1 lowers the %2 residual only from %3 to %4</source>
        <translation>die angepasste Kurve %1 senkt das Residuum (%2) nur von %3 auf %4</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="110"/>
        <source>the %1 residual of sRGB, %2, is within what photos read rightly as sRGB show (below %3), so the fitted %4 is not trusted</source>
        <translation>das Residuum (%1) von sRGB, %2, liegt im Bereich dessen, was zu Recht als sRGB gelesene Fotos zeigen (unter %3), daher wird der angepassten Kurve %4 nicht vertraut</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="113"/>
        <source>the fitted %1 spans %2 stops between codes 128 and 254 (sRGB 2.2, at most %3 trusted), but the photo&apos;s noise was measured at only %4 code level in that half (%5 needed), so the shoulder is an extrapolation</source>
        <translation>die angepasste Kurve %1 umfasst %2 Blendenstufen zwischen den Codes 128 und 254 (sRGB 2,2, höchstens %3 glaubhaft), aber das Rauschen des Fotos wurde in dieser Hälfte nur auf %4 Code-Stufe gemessen (%5 nötig), die Schulter ist also extrapoliert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="117"/>
        <source>the fitted %1 spans %2 stops between codes 128 and 254 (sRGB 2.2, at most %3 trusted), but the photo&apos;s noise was measured at only %4 code levels in that half (%5 needed), so the shoulder is an extrapolation</source>
        <translation>die angepasste Kurve %1 umfasst %2 Blendenstufen zwischen den Codes 128 und 254 (sRGB 2,2, höchstens %3 glaubhaft), aber das Rauschen des Fotos wurde in dieser Hälfte nur auf %4 Code-Stufen gemessen (%5 nötig), die Schulter ist also extrapoliert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="121"/>
        <source>too little evidence for a curve other than sRGB (%1)</source>
        <translation>zu wenig Anhaltspunkte für eine andere Kurve als sRGB (%1)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="123"/>
        <source>an implausible curve was refused (%1); using sRGB</source>
        <translation>eine unplausible Kurve wurde abgelehnt (%1); verwende sRGB</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="125"/>
        <source>the light fit&apos;s residual with the fitted %1 is %2, with sRGB %3</source>
        <translation>das Residuum der Lichtanpassung ist mit der angepassten Kurve %1 %2, mit sRGB %3</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="127"/>
        <source>the estimated curve was not used (%1); using sRGB</source>
        <translation>die geschätzte Kurve wurde nicht verwendet (%1); verwende sRGB</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="128"/>
        <source>the fitted %1 lies at the family&apos;s bound (%2): the camera&apos;s curve may be stronger than the family holds</source>
        <translation>die angepasste Kurve %1 liegt an der Grenze ihrer Familie (%2): die Kurve der Kamera kann stärker sein, als die Familie fasst</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="131"/>
        <source>%1; using sRGB (give camera.response to choose)</source>
        <translation>%1; verwende sRGB (camera.response angeben, um zu wählen)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="132"/>
        <source>the photo is empty</source>
        <translation>das Foto ist leer</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="133"/>
        <source>most of the photo is clipped to black or white</source>
        <translation>der Großteil des Fotos ist zu Schwarz oder Weiß abgeschnitten</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="134"/>
        <source>the photo is nearly one flat colour</source>
        <translation>das Foto ist fast eine einzige flache Farbe</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="135"/>
        <source>the photo is nearly binary (%1 grey levels in use)</source>
        <translation>das Foto ist fast binär (%1 Graustufen belegt)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="136"/>
        <source>too few clean edges between flat regions (%1 of %2 needed)</source>
        <translation>zu wenige saubere Kanten zwischen flachen Bereichen (%1 von %2 nötigen)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="138"/>
        <source>the edges cover only codes %1 to %2</source>
        <translation>die Kanten decken nur die Codes %1 bis %2 ab</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="139"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="140"/>
        <source>too few flat regions to measure the noise (%1 flat 8 x 8 blocks)</source>
        <translation>zu wenige flache Bereiche, um das Rauschen zu messen (%1 flache 8 x 8-Blöcke)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="142"/>
        <source>the flat regions cover too few codes to measure the noise against them</source>
        <translation>die flachen Bereiche decken zu wenige Codes ab, um das Rauschen über sie zu messen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="144"/>
        <source>the photo shows no measurable noise</source>
        <translation>das Foto zeigt kein messbares Rauschen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="155"/>
        <source>none marked</source>
        <translation>keine markiert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="156"/>
        <source>no sun marked</source>
        <translation>keine Sonne markiert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="157"/>
        <source>none inserted</source>
        <translation>keine eingefügt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="158"/>
        <source>the lights are kept as estimated (initial lights asked for)</source>
        <translation>die Lichter bleiben wie geschätzt (erste Lichter verlangt)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="160"/>
        <source>turned off</source>
        <translation>ausgeschaltet</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="161"/>
        <source>no light marked</source>
        <translation>kein Licht markiert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="162"/>
        <source>every light locked or given (&quot;refine&quot;: false)</source>
        <translation>jedes Licht gesperrt oder vorgegeben („refine“: false)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="163"/>
        <source>every light locked</source>
        <translation>jedes Licht gesperrt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="164"/>
        <source>the working copy is the photo</source>
        <translation>die Arbeitskopie ist das Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="165"/>
        <source>the lights were not refined</source>
        <translation>die Lichter wurden nicht verfeinert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="166"/>
        <source>no light moved</source>
        <translation>kein Licht bewegt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="167"/>
        <source>lights moved by at most %1 % of their size (under %2 %): the first estimate&apos;s lights are kept</source>
        <translation>Lichter um höchstens %1 % ihrer Größe bewegt (unter %2 %): die Lichter der ersten Schätzung bleiben</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="170"/>
        <source>camera.vignetting is &quot;none&quot; (the default)</source>
        <translation>camera.vignetting ist &quot;none&quot; (die Voreinstellung)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="172"/>
        <source>%1 x %2 px</source>
        <translation>%1 x %2 px</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="173"/>
        <source>linear photo</source>
        <translation>lineares Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="174"/>
        <source>estimated</source>
        <translation>geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="175"/>
        <source>the photo area-averaged</source>
        <translation>das Foto flächengemittelt verkleinert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="176"/>
        <source>the photo&apos;s own size</source>
        <translation>die eigene Größe des Fotos</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="177"/>
        <source>estimated from the photo</source>
        <translation>aus dem Foto geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="178"/>
        <source>the file&apos;s vanishing points and back wall</source>
        <translation>Fluchtpunkte und Rückwand aus der Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="179"/>
        <source>estimated from the photo once, for the response check&apos;s copy</source>
        <translation>einmal aus dem Foto geschätzt, für die Kopie der Prüfung der Kamerakennlinie</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="181"/>
        <source>%1 x %2 m</source>
        <translation>%1 x %2 m</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="182"/>
        <source>%1 m high</source>
        <translation>%1 m hoch</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="183"/>
        <source>%1 matte</source>
        <translation>%1 Maske</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="184"/>
        <source>%1 mattes</source>
        <translation>%1 Masken</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="185"/>
        <source>v %1 applied</source>
        <translation>v %1 angewandt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="186"/>
        <source>the light fit&apos;s residual shows %1</source>
        <translation>das Residuum der Lichtanpassung zeigt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="187"/>
        <source>the light fit run again</source>
        <translation>die Lichtanpassung erneut ausgeführt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="188"/>
        <source>%1 surface built</source>
        <translation>%1 Fläche gebaut</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="189"/>
        <source>%1 surfaces built</source>
        <translation>%1 Flächen gebaut</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="190"/>
        <source>%1 surface</source>
        <translation>%1 Fläche</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="191"/>
        <source>%1 surfaces</source>
        <translation>%1 Flächen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="192"/>
        <source>%1 reflective</source>
        <translation>%1 spiegelnd</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="193"/>
        <source>%1 outlined</source>
        <translation>%1 umrissen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="194"/>
        <source>%1 placed in 3D</source>
        <translation>%1 in 3D platziert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="195"/>
        <source>%1 sun</source>
        <translation>%1 Sonne</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="196"/>
        <source>%1 suns</source>
        <translation>%1 Sonnen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="197"/>
        <source>%1 sky through an unseen window</source>
        <translation>%1 Himmel durch ein nicht sichtbares Fenster</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="198"/>
        <source>%1 skies through unseen windows</source>
        <translation>%1 Himmel durch nicht sichtbare Fenster</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="199"/>
        <source>%1 light</source>
        <translation>%1 Licht</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="200"/>
        <source>%1 lights</source>
        <translation>%1 Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="201"/>
        <source>%1 pass</source>
        <translation>%1 Durchgang</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="202"/>
        <source>%1 passes</source>
        <translation>%1 Durchgänge</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="203"/>
        <source>the first estimate&apos;s rays replayed</source>
        <translation>die Strahlen der ersten Schätzung wiederverwendet</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="204"/>
        <source>%1 points x %2 rays</source>
        <translation>%1 Punkte x %2 Strahlen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="205"/>
        <source>%1 light fit iterations</source>
        <translation>%1 Iterationen der Lichtanpassung</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="206"/>
        <source>%1 of %2 light refined</source>
        <translation>%1 von %2 Licht verfeinert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="207"/>
        <source>%1 of %2 lights refined</source>
        <translation>%1 von %2 Lichtern verfeinert</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="208"/>
        <source>%1 evaluation</source>
        <translation>%1 Auswertung</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="209"/>
        <source>%1 evaluations</source>
        <translation>%1 Auswertungen</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="210"/>
        <source>lights moved by at most %1 % of their size; the first estimate fits the photo better (log residual %2 against %3) and is kept; the refit took %4</source>
        <translation>Lichter um höchstens %1 % ihrer Größe bewegt; die erste Schätzung passt besser zum Foto (Log-Residuum %2 gegen %3) und bleibt; die Neuanpassung brauchte %4</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="213"/>
        <source>lights moved by at most %1 % of their size; the refit is kept (log residual %2 against the first estimate&apos;s %3)</source>
        <translation>Lichter um höchstens %1 % ihrer Größe bewegt; die Neuanpassung bleibt (Log-Residuum %2 gegen %3 der ersten Schätzung)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="216"/>
        <source>from %1 x %2 px: maps %3 s</source>
        <translation>aus %1 x %2 px: Karten %3 s</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="217"/>
        <source>surfaces cast %1 s</source>
        <translation>Flächen je Pixel %1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="218"/>
        <source>%1 object</source>
        <translation>%1 Objekt</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="219"/>
        <source>%1 objects</source>
        <translation>%1 Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="220"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="223"/>
        <source>the curve kept: %1</source>
        <translation>Kurve behalten: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="224"/>
        <source>sRGB kept: %1</source>
        <translation>sRGB behalten: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="225"/>
        <source>the light fit&apos;s residual with the fitted %1 is %2</source>
        <translation>das Residuum der Lichtanpassung ist mit der angepassten Kurve %1 %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="23"/>
        <source>toe_shoulder (power %1, toe %2, shoulder %3)</source>
        <translation>toe_shoulder (Exponent %1, Fuß %2, Schulter %3)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="27"/>
        <source>vanishing point %1: only %2 supporting line(s); it rests on the other two</source>
        <translation>Fluchtpunkt %1: nur %2 stützende Linie(n); er stützt sich auf die anderen beiden</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="29"/>
        <source>vanishing point %1: its lines are nearly parallel in the photo, so its distance is uncertain</source>
        <translation>Fluchtpunkt %1: seine Linien sind im Foto fast parallel, daher ist seine Entfernung unsicher</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="227"/>
        <source>with sRGB %1; on %2 x %3 copies %4 against %5</source>
        <translation>mit sRGB %1; auf Kopien von %2 x %3 px %4 gegen %5</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="228"/>
        <source>with sRGB %1; no quick comparison</source>
        <translation>mit sRGB %1; kein schneller Vergleich</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="229"/>
        <source>log ratio %1 beyond %2</source>
        <translation>Log-Verhältnis %1 jenseits von %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="230"/>
        <source>log ratio %1 within %2</source>
        <translation>Log-Verhältnis %1 innerhalb von %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="235"/>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="236"/>
        <source>header line %1</source>
        <translation>Kopfzeile %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="237"/>
        <source>vertex %1</source>
        <translation>Eckpunkt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="238"/>
        <source>face %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="239"/>
        <source>sun %1</source>
        <translation>Sonne %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="240"/>
        <source>lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="241"/>
        <source>estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="242"/>
        <source>lighting</source>
        <translation>Beleuchtung</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="243"/>
        <source>lighting (refit)</source>
        <translation>Beleuchtung (neu angepasst)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="244"/>
        <source>light refinement</source>
        <translation>Verfeinerung der Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="245"/>
        <source>decomposition</source>
        <translation>Zerlegung</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="246"/>
        <source>layout</source>
        <translation>Raumaufteilung</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="247"/>
        <source>camera response</source>
        <translation>Kamerakennlinie</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="248"/>
        <source>kept sRGB</source>
        <translation>sRGB beibehalten</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="311"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>inlay::studio::FinalRender</name>
    <message>
        <location filename="../app/studio/final_render.cpp" line="81"/>
        <source>Render Final Image cancelled; nothing was written.</source>
        <translation>Endgültiges Bild abgebrochen; nichts wurde geschrieben.</translation>
    </message>
    <message>
        <location filename="../app/studio/final_render.cpp" line="129"/>
        <source>Wrote %1: %2 × %3, %4 samples per pixel at most (%5 on average), estimated error %6 before denoising, %7 s</source>
        <translation>%1 geschrieben: %2 × %3, höchstens %4 Samples pro Pixel (%5 im Mittel), geschätzter Fehler %6 vor dem Entrauschen, %7 s</translation>
    </message>
    <message>
        <location filename="../app/studio/final_render.cpp" line="131"/>
        <source>Wrote %1: %2 × %3, %4 samples per pixel at most (%5 on average), estimated error %6, %7 s</source>
        <translation>%1 geschrieben: %2 × %3, höchstens %4 Samples pro Pixel (%5 im Mittel), geschätzter Fehler %6, %7 s</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LayersDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="254"/>
        <source>Layers</source>
        <translation>Ebenen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="255"/>
        <source>Composite</source>
        <translation>Komposit</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="255"/>
        <source>Photo</source>
        <translation>Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="255"/>
        <source>Albedo</source>
        <translation>Albedo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="256"/>
        <source>Direct light</source>
        <translation>Direktes Licht</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="256"/>
        <source>With objects</source>
        <translation>Mit Objekten</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="256"/>
        <source>Without objects</source>
        <translation>Ohne Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="257"/>
        <source>Mask</source>
        <translation>Maske</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="257"/>
        <source>Difference</source>
        <translation>Differenz</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LibraryDock</name>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="23"/>
        <source>Chair</source>
        <translation>Stuhl</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="24"/>
        <source>Armchair</source>
        <translation>Sessel</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="25"/>
        <source>Sofa</source>
        <translation>Sofa</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="26"/>
        <source>Coffee table</source>
        <translation>Couchtisch</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="27"/>
        <source>Dining table</source>
        <translation>Esstisch</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="28"/>
        <source>Stool</source>
        <translation>Hocker</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="29"/>
        <source>Floor lamp</source>
        <translation>Stehlampe</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="30"/>
        <source>Table lamp</source>
        <translation>Tischlampe</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="31"/>
        <source>Vase</source>
        <translation>Vase</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="32"/>
        <source>Potted plant</source>
        <translation>Topfpflanze</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="33"/>
        <source>Bookshelf</source>
        <translation>Bücherregal</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="34"/>
        <source>Rug</source>
        <translation>Teppich</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="106"/>
        <source>Library</source>
        <translation>Bibliothek</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="109"/>
        <source>no library.json in $INLAY_MODELS_DIR, &lt;prefix&gt;/share/inlay/models or resources/models</source>
        <translation>keine library.json in $INLAY_MODELS_DIR, &lt;prefix&gt;/share/inlay/models oder resources/models</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="112"/>
        <source>The model library could not be shown: %1</source>
        <translation>Die Modellbibliothek kann nicht angezeigt werden: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="118"/>
        <source>%1
%2 × %3 × %4 m (width × depth × height)
Drag it into the photo.</source>
        <translation>%1
%2 × %3 × %4 m (Breite × Tiefe × Höhe)
Ins Foto ziehen, um es einzusetzen.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LogDock</name>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="31"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="39"/>
        <source>%1 The scene could not be prepared: %2</source>
        <translation>%1 Die Szene konnte nicht vorbereitet werden: %2</translation>
    </message>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="46"/>
        <source>%1 Prepared the scene in %2 s:</source>
        <translation>%1 Szene in %2 s vorbereitet:</translation>
    </message>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="49"/>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
</context>
<context>
    <name>inlay::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="90"/>
        <source>Reading the photo</source>
        <translation>Foto wird gelesen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="91"/>
        <source>Estimating the camera</source>
        <translation>Kamera wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="92"/>
        <source>Fitting the room</source>
        <translation>Raum wird angepasst</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="93"/>
        <source>Estimating the lighting</source>
        <translation>Beleuchtung wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="95"/>
        <source>Placing the objects</source>
        <translation>Objekte werden platziert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="500"/>
        <source>Samples per pixel of the shown composite</source>
        <translation>Samples pro Pixel des angezeigten Komposits</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="501"/>
        <source>Samples per second of the renderer (millions)</source>
        <translation>Samples pro Sekunde des Renderers (Millionen)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="502"/>
        <source>Estimated error (RMSE in sRGB) where the objects change the photo</source>
        <translation>Geschätzter Fehler (RMSE in sRGB), wo die Objekte das Foto verändern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="503"/>
        <source>Render time since the last change</source>
        <translation>Renderzeit seit der letzten Änderung</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="504"/>
        <source>Zoom</source>
        <translation>Zoom</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="138"/>
        <location filename="../app/studio/main_window.cpp" line="535"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="645"/>
        <source>Preparing the scene: %1…</source>
        <translation>Szene wird vorbereitet: %1 …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="445"/>
        <source>&amp;Open Scene…</source>
        <translation>Szene &amp;öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="486"/>
        <source>Open a scene file (.json)</source>
        <translation>Eine Szenendatei (.json) öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="446"/>
        <source>Open &amp;Photo…</source>
        <translation>&amp;Foto öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="487"/>
        <source>Start a new scene from a photo</source>
        <translation>Eine neue Szene aus einem Foto beginnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="447"/>
        <source>Open &amp;Example</source>
        <translation>&amp;Beispiel öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="448"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="449"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="450"/>
        <source>&amp;Export Composite…</source>
        <translation>Komposit &amp;exportieren …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="488"/>
        <source>Write the current composite as PNG, JPEG, TIFF or EXR</source>
        <translation>Das aktuelle Komposit als PNG, JPEG, TIFF oder EXR schreiben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="451"/>
        <source>Export Shown &amp;Layer…</source>
        <translation>Angezeigte &amp;Ebene exportieren…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="490"/>
        <source>Write the layer the viewport shows (albedo, mask, …) as an 8-bit image</source>
        <translation>Die angezeigte Ebene (Albedo, Maske, …) als 8-Bit-Bild schreiben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="452"/>
        <source>Export Scene as &amp;glTF…</source>
        <translation>Szene als &amp;glTF exportieren…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="492"/>
        <source>Write the room, its lights, the camera and the objects as glTF 2.0, to go on in Blender</source>
        <translation>Raum, Lichter, Kamera und Objekte als glTF 2.0 schreiben, um in Blender weiterzuarbeiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="460"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="542"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="543"/>
        <source>&amp;Redo</source>
        <translation>Wi&amp;ederholen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="461"/>
        <source>Insert &amp;Sphere</source>
        <translation>&amp;Kugel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="493"/>
        <source>Stand a sphere on the floor in the middle of the photo</source>
        <translation>Eine Kugel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="462"/>
        <source>Insert &amp;Cube</source>
        <translation>&amp;Würfel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="494"/>
        <source>Stand a cube on the floor in the middle of the photo</source>
        <translation>Einen Würfel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="463"/>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="495"/>
        <source>Delete the selected object or mark</source>
        <translation>Das ausgewählte Objekt oder die ausgewählte Markierung löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="474"/>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="475"/>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="476"/>
        <source>&amp;Fit to Window</source>
        <translation>An &amp;Fenster anpassen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="477"/>
        <source>&amp;Before (Photo Only)</source>
        <translation>&amp;Vorher (nur Foto)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="496"/>
        <source>Toggle between the photo and the composite with the objects</source>
        <translation>Zwischen dem Foto und dem Komposit mit den Objekten umschalten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="478"/>
        <source>&amp;Accept Estimated Box</source>
        <translation>Geschätzten &amp;Raum übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="497"/>
        <source>Keep the estimated back wall as yours</source>
        <translation>Die geschätzte Rückwand als Ihre behalten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="479"/>
        <source>Estimate the &amp;Box Again</source>
        <translation>Raum &amp;neu schätzen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="498"/>
        <source>Forget your corners of the back wall</source>
        <translation>Ihre Ecken der Rückwand verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="480"/>
        <source>&amp;Prepare the Scene Again</source>
        <translation>Szene erneut &amp;vorbereiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="499"/>
        <source>Estimate the camera, room and lighting again (after a cancel)</source>
        <translation>Kamera, Raum und Beleuchtung erneut schätzen (nach einem Abbruch)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="481"/>
        <source>&amp;Vanishing Lines and Confidence</source>
        <translation>&amp;Fluchtlinien und Konfidenz</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="505"/>
        <source>&amp;Select and Move</source>
        <translation>&amp;Auswählen und verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="505"/>
        <source>Outline a &amp;Light</source>
        <translation>&amp;Lampe umreißen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="506"/>
        <source>Sun &amp;Shaft</source>
        <translation>&amp;Sonnenstrahl</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="506"/>
        <source>&amp;Table Top or Step</source>
        <translation>&amp;Tischplatte oder Stufe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="507"/>
        <source>&amp;Occluder Strokes</source>
        <translation>&amp;Verdecker-Striche</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="485"/>
        <source>&amp;About Inlay</source>
        <translation>&amp;Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="94"/>
        <source>Refining the lights</source>
        <translation>Lichter verfeinern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="453"/>
        <source>&amp;Render Final Image…</source>
        <translation>Endgültiges Bild &amp;rendern…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="455"/>
        <source>Render the composite at the photo&apos;s full resolution until it is clean, then save it (PNG, JPEG, TIFF or EXR)</source>
        <translation>Das Komposit in der vollen Auflösung des Fotos rendern, bis es rauschfrei ist, dann speichern (PNG, JPEG, TIFF oder EXR)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="457"/>
        <source>Before/After &amp;Split</source>
        <translation>Vorher/Nachher-&amp;Teilung</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="459"/>
        <source>The photo left of a divider, the composite right of it; drag the divider</source>
        <translation>Links einer Trennlinie das Foto, rechts das Komposit; die Trennlinie lässt sich ziehen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="464"/>
        <source>Insert &amp;Model…</source>
        <translation>&amp;Modell einfügen…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="466"/>
        <source>Stand a 3D model (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) on the floor; or drop the file where it should stand</source>
        <translation>Ein 3D-Modell (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) auf den Boden stellen; oder die Datei dort ablegen, wo es stehen soll</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="468"/>
        <source>D&amp;uplicate</source>
        <translation>D&amp;uplizieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="469"/>
        <source>Stand a copy of the selected object beside it</source>
        <translation>Eine Kopie des gewählten Objekts daneben stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="470"/>
        <source>Re&amp;name…</source>
        <translation>&amp;Umbenennen…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="471"/>
        <source>Rename the selected object (in the Scene list)</source>
        <translation>Das gewählte Objekt umbenennen (in der Szenenliste)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="472"/>
        <source>&amp;Hide or Show</source>
        <translation>Aus- oder &amp;Einblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="473"/>
        <source>Hide the selected object from the render, or show it again</source>
        <translation>Das gewählte Objekt aus dem Rendering ausblenden oder wieder einblenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="482"/>
        <source>&amp;Denoise Preview</source>
        <translation>Vorschau &amp;entrauschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="484"/>
        <source>Smooth the render&apos;s noise where the objects change the photo (the rest stays the photo)</source>
        <translation>Das Rauschen des Renderings glätten, wo die Objekte das Foto ändern (der Rest bleibt das Foto)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="507"/>
        <source>&amp;Vanishing Lines (X, Y, Z)</source>
        <translation>&amp;Fluchtlinien (X, Y, Z)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="509"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="510"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="511"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="512"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="513"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="514"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="515"/>
        <source>System Default</source>
        <translation>Systemvorgabe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="516"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="517"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="542"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Rückgängig: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="543"/>
        <source>&amp;Redo %1</source>
        <translation>&amp;Wiederherstellen: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="552"/>
        <location filename="../app/studio/main_window.cpp" line="567"/>
        <location filename="../app/studio/main_window.cpp" line="644"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="552"/>
        <location filename="../app/studio/main_window.cpp" line="933"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="553"/>
        <location filename="../app/studio/main_window.cpp" line="1378"/>
        <source>Inlay</source>
        <translation>Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="587"/>
        <source>The scene could not be prepared</source>
        <translation>Die Szene konnte nicht vorbereitet werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/main_window.cpp" line="596"/>
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (und %n weiterer Hinweis)</numerusform>
            <numerusform>%1 (und %n weitere Hinweise)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="625"/>
        <source>%1: the scene could not be prepared, so the model has nowhere to stand.</source>
        <translation>%1: Die Szene ließ sich nicht vorbereiten, das Modell hat also keinen Platz.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="530"/>
        <location filename="../app/studio/main_window.cpp" line="665"/>
        <source>– spp</source>
        <translation>– spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="532"/>
        <location filename="../app/studio/main_window.cpp" line="658"/>
        <location filename="../app/studio/main_window.cpp" line="666"/>
        <location filename="../app/studio/main_window.cpp" line="680"/>
        <source>– samples/s</source>
        <translation>– Samples/s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="533"/>
        <location filename="../app/studio/main_window.cpp" line="667"/>
        <source>error –</source>
        <translation>Fehler –</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="534"/>
        <location filename="../app/studio/main_window.cpp" line="668"/>
        <source>– s</source>
        <translation>– s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="530"/>
        <location filename="../app/studio/main_window.cpp" line="657"/>
        <source>final, %1 spp</source>
        <translation>endgültig, %1 spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="529"/>
        <location filename="../app/studio/main_window.cpp" line="672"/>
        <source>preview 1/%1</source>
        <translation>Vorschau 1/%1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="529"/>
        <location filename="../app/studio/main_window.cpp" line="673"/>
        <source>%1 spp, done</source>
        <translation>%1 spp, fertig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="674"/>
        <source>%1 spp</source>
        <translation>%1 spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1394"/>
        <source>The final image %1 is still being rendered (%2 % done). Cancel the render? Nothing is written then, and an earlier file of that name stays as it was.</source>
        <translation>Das endgültige Bild %1 wird noch gerendert (%2 % fertig). Das Rendern abbrechen? Dann wird nichts geschrieben, und eine frühere Datei dieses Namens bleibt, wie sie war.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1402"/>
        <source>Keep Rendering</source>
        <translation>Weiter rendern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1421"/>
        <source>Cancel the Render and Close</source>
        <translation>Rendern abbrechen und schließen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="533"/>
        <location filename="../app/studio/main_window.cpp" line="659"/>
        <location filename="../app/studio/main_window.cpp" line="675"/>
        <source>error %1</source>
        <translation>Fehler %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="532"/>
        <location filename="../app/studio/main_window.cpp" line="679"/>
        <source>%1 M samples/s</source>
        <translation>%1 Mio. Samples/s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="534"/>
        <location filename="../app/studio/main_window.cpp" line="660"/>
        <location filename="../app/studio/main_window.cpp" line="681"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="691"/>
        <source>%1 (new scene)</source>
        <translation>%1 (neue Szene)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="692"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="693"/>
        <source>%1[*] — Inlay</source>
        <translation>%1[*] — Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="714"/>
        <source>Cancel the Render and Open</source>
        <translation>Rendern abbrechen und öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="718"/>
        <source>Cannot open</source>
        <translation>Öffnen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="718"/>
        <source>%1: no such file</source>
        <translation>%1: Datei nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="724"/>
        <source>Cannot open the scene</source>
        <translation>Die Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="743"/>
        <location filename="../app/studio/main_window.cpp" line="753"/>
        <source>Cannot open the example</source>
        <translation>Das Beispiel kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="743"/>
        <source>The example scene is not installed.</source>
        <translation>Die Beispielszene ist nicht installiert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="753"/>
        <source>Cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="763"/>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="764"/>
        <source>Inlay scenes (*.json);;All files (*)</source>
        <translation>Inlay-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="771"/>
        <source>Open Photo</source>
        <translation>Foto öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="772"/>
        <source>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)</source>
        <translation>Fotos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="779"/>
        <source>Cannot save the scene</source>
        <translation>Die Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="783"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="799"/>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="799"/>
        <source>Inlay scenes (*.json)</source>
        <translation>Inlay-Szenen (*.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="807"/>
        <location filename="../app/studio/main_window.cpp" line="838"/>
        <location filename="../app/studio/main_window.cpp" line="1034"/>
        <location filename="../app/studio/main_window.cpp" line="1065"/>
        <source>Nothing to export</source>
        <translation>Nichts zu exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="807"/>
        <location filename="../app/studio/main_window.cpp" line="838"/>
        <source>The composite has not been rendered yet.</source>
        <translation>Das Komposit wurde noch nicht gerendert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="830"/>
        <location filename="../app/studio/main_window.cpp" line="1054"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="830"/>
        <location filename="../app/studio/main_window.cpp" line="1054"/>
        <source>JPEG image (*.jpg *.jpeg)</source>
        <translation>JPEG-Bild (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="830"/>
        <location filename="../app/studio/main_window.cpp" line="1055"/>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>TIFF-Bild (*.tif *.tiff)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="831"/>
        <source>OpenEXR, linear (*.exr)</source>
        <translation>OpenEXR, linear (*.exr)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="810"/>
        <source>Export Composite</source>
        <translation>Komposit exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="846"/>
        <source>Cannot export the composite</source>
        <translation>Das Komposit kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="851"/>
        <source>Exported %1 (the final render)</source>
        <translation>%1 exportiert (das endgültige Bild)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="856"/>
        <source>Exported %1 (%2 spp, the preview&apos;s %3 × %4; Render Final Image writes the photo&apos;s full size)</source>
        <translation>%1 exportiert (%2 spp, die Vorschau mit %3 × %4; Endgültiges Bild rendern schreibt die volle Größe des Fotos)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="864"/>
        <source>Exported %1 (%2 spp)</source>
        <translation>%1 exportiert (%2 spp)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="887"/>
        <source>All four steps done. View &gt; Steps shows them again.</source>
        <translation>Alle vier Schritte erledigt. Ansicht &gt; Schritte zeigt sie wieder.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="893"/>
        <location filename="../app/studio/main_window.cpp" line="908"/>
        <source>Nothing to render</source>
        <translation>Nichts zu rendern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="901"/>
        <location filename="../app/studio/main_window.cpp" line="934"/>
        <location filename="../app/studio/main_window.cpp" line="1393"/>
        <source>Render Final Image</source>
        <translation>Endgültiges Bild rendern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="912"/>
        <source>A final image is being rendered already.</source>
        <translation>Ein endgültiges Bild wird bereits gerendert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="919"/>
        <location filename="../app/studio/main_window.cpp" line="924"/>
        <source>Cannot render the final image</source>
        <translation>Das endgültige Bild kann nicht gerendert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="920"/>
        <source>%1: choose a .png, .jpg, .tif or .exr file.</source>
        <translation>%1: bitte eine .png-, .jpg-, .tif- oder .exr-Datei wählen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="925"/>
        <source>%1: the folder %2 does not exist.</source>
        <translation>%1: der Ordner %2 existiert nicht.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="933"/>
        <location filename="../app/studio/main_window.cpp" line="954"/>
        <source>Rendering the final image…</source>
        <translation>Das endgültige Bild wird gerendert…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="942"/>
        <source>Rendering the final image: %1 samples per pixel at most, estimated error %2 (target %3), %4 s</source>
        <translation>Endgültiges Bild: höchstens %1 Samples pro Pixel, geschätzter Fehler %2 (Ziel %3), %4 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="978"/>
        <source>Cannot write the final image</source>
        <translation>Das endgültige Bild kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="999"/>
        <source>Final render shown (%1, %2 × %3); the next edit returns to the live preview.</source>
        <translation>Endgültiges Bild angezeigt (%1, %2 × %3); die nächste Änderung kehrt zur Live-Vorschau zurück.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1003"/>
        <source>Final render (%1 × %2, saved as %3): shown until the next edit</source>
        <translation>Endgültiges Bild (%1 × %2, gespeichert als %3): angezeigt bis zur nächsten Änderung</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1022"/>
        <source>glTF 2.0, separate files (*.gltf)</source>
        <translation>glTF 2.0, getrennte Dateien (*.gltf)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1022"/>
        <source>glTF 2.0, binary (*.glb)</source>
        <translation>glTF 2.0, binär (*.glb)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1023"/>
        <source>Export Scene as glTF</source>
        <translation>Szene als glTF exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="893"/>
        <location filename="../app/studio/main_window.cpp" line="908"/>
        <location filename="../app/studio/main_window.cpp" line="1034"/>
        <source>The scene is not prepared yet.</source>
        <translation>Die Szene ist noch nicht vorbereitet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1041"/>
        <source>Cannot export the scene</source>
        <translation>Die Szene kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1053"/>
        <source>Export Shown Layer</source>
        <translation>Angezeigte Ebene exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1065"/>
        <source>This layer has not been made yet.</source>
        <translation>Diese Ebene wurde noch nicht berechnet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1072"/>
        <source>Cannot export the layer</source>
        <translation>Die Ebene kann nicht exportiert werden</translation>
    </message>
    <message>
        <source>%1: cannot write (%2)</source>
        <translation type="vanished">%1: kann nicht geschrieben werden (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1044"/>
        <location filename="../app/studio/main_window.cpp" line="1075"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1105"/>
        <source>About Inlay</source>
        <translation>Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1106"/>
        <source>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Inserts synthetic objects into an ordinary photograph: a box room is fitted to the photo, its lights and reflectance are estimated, and a path tracer renders the objects into it (after Karsch et al., 2011).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Fügt synthetische Objekte in ein gewöhnliches Foto ein: Ein Quaderraum wird an das Foto angepasst, seine Lichter und Reflexionsgrade werden geschätzt, und ein Pfadverfolger rendert die Objekte hinein (nach Karsch et al., 2011).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1115"/>
        <source>There is no floor in the middle of the photo to stand an object on.</source>
        <translation>In der Bildmitte gibt es keinen Boden, auf dem ein Objekt stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1142"/>
        <source>Insert Model</source>
        <translation>Modell einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1150"/>
        <source>%1: open a photo first; the model needs a room to stand in.</source>
        <translation>%1: Zuerst ein Foto öffnen; das Modell braucht einen Raum, in dem es steht.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1154"/>
        <source>%1: not a model file Inlay reads (%2).</source>
        <translation>%1: keine Modelldatei, die Inlay liest (%2).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1169"/>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1179"/>
        <source>%1 goes in once the scene is prepared.</source>
        <translation>%1 wird eingefügt, sobald die Szene vorbereitet ist.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1220"/>
        <source>%1: there is no floor, table top or step under the drop point to stand it on.</source>
        <translation>%1: Unter der Ablagestelle gibt es keinen Boden, keine Tischplatte und keine Stufe, auf der es stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1222"/>
        <source>%1: there is no floor in the middle of the photo to stand it on.</source>
        <translation>%1: In der Mitte des Fotos gibt es keinen Boden, auf dem es stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1192"/>
        <source>%1 is %2 m high at its own size, taller than the room (%3 m): it was inserted %4 m high instead (change Height in Properties).</source>
        <translation>%1 ist in seiner eigenen Größe %2 m hoch, höher als der Raum (%3 m): Es wurde stattdessen %4 m hoch eingefügt (Höhe in den Eigenschaften ändern).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1205"/>
        <source>%1 is %2 m wide at its own size, wider than the room (%3 m): it was inserted %4 m high instead (change Height in Properties).</source>
        <translation>%1 ist in seiner eigenen Größe %2 m breit, breiter als der Raum (%3 m): Es wurde stattdessen %4 m hoch eingefügt (Höhe in den Eigenschaften ändern).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1248"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1252"/>
        <source>Inserted %1, %2 m high (its own size).</source>
        <translation>%1 eingefügt, %2 m hoch (seine eigene Größe).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1253"/>
        <source>Inserted %1, %2 m high.</source>
        <translation>%1 eingefügt, %2 m hoch.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1262"/>
        <source>Cannot insert the model</source>
        <translation>Das Modell lässt sich nicht einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1282"/>
        <source>Select an object to rename.</source>
        <translation>Ein Objekt zum Umbenennen auswählen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1312"/>
        <source>Models</source>
        <translation>Modelle</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1314"/>
        <source>Insert %1</source>
        <translation>%1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1339"/>
        <source>a new scene</source>
        <translation>einer neuen Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1342"/>
        <source>Restore unsaved work?</source>
        <translation>Ungesicherte Arbeit wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1343"/>
        <source>Inlay did not close properly. Unsaved work on %1 was kept at %2. Restore it?</source>
        <translation>Inlay wurde nicht ordnungsgemäß beendet. Ungesicherte Arbeit an %1 wurde um %2 aufbewahrt. Wiederherstellen?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1347"/>
        <source>&amp;Restore</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1348"/>
        <source>&amp;Discard</source>
        <translation>&amp;Verwerfen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1365"/>
        <source>Cannot restore the unsaved work</source>
        <translation>Die ungesicherte Arbeit kann nicht wiederhergestellt werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1371"/>
        <source>Restored the unsaved work.</source>
        <translation>Die ungesicherte Arbeit wurde wiederhergestellt.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1378"/>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>Die Szene hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ModelImportText</name>
    <message>
        <location filename="../app/studio/model_import.cpp" line="19"/>
        <source>%1 km</source>
        <translation>%1 km</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="20"/>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="21"/>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="22"/>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="23"/>
        <source>%1 µm</source>
        <translation>%1 µm</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="38"/>
        <source>%1 files do not state their unit: %2 was scaled to %3 high (change Height in Properties).</source>
        <translation>%1-Dateien nennen ihre Einheit nicht: %2 wurde auf %3 Höhe skaliert (Höhe in den Eigenschaften ändern).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="50"/>
        <source>%1 says it is %2 high, an absurd size: it was inserted %3 high instead (change Height in Properties).</source>
        <translation>%1 gibt %2 Höhe an, eine absurde Größe: Es wurde stattdessen %3 hoch eingefügt (Höhe in den Eigenschaften ändern).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="109"/>
        <source>%1 names files that are not beside it (%2): its materials&apos; own colours are used, or a grey default.</source>
        <translation>%1 nennt Dateien, die nicht daneben liegen (%2): die eigenen Farben seiner Materialien werden verwendet, sonst ein Grau.</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="114"/>
        <source>%1&apos;s image textures are not rendered: Inlay uses its materials&apos; base colour, metallic and roughness values.</source>
        <translation>Die Bildtexturen von %1 werden nicht gerendert: Inlay verwendet Grundfarbe, Metallizität und Rauheit seiner Materialien.</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="137"/>
        <source>3D models (%1)</source>
        <translation>3D-Modelle (%1)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="138"/>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="152"/>
        <source>%1: not a model file Inlay reads (%2).</source>
        <translation>%1: keine Modelldatei, die Inlay liest (%2).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="170"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="174"/>
        <source>(Inlay inserts models of up to %1 triangles.)</source>
        <translation>(Inlay fügt Modelle mit bis zu %1 Dreiecken ein.)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="179"/>
        <source>%1: the model is flat (it has no height), so it cannot stand in the room.</source>
        <translation>%1: Das Modell ist flach (es hat keine Höhe) und kann daher nicht im Raum stehen.</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="190"/>
        <source>%1 has no normals: it is shaded flat.</source>
        <translation>%1 hat keine Normalen: Es wird flach schattiert.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PrepareWorker</name>
    <message>
        <location filename="../app/studio/prepare_worker.cpp" line="98"/>
        <source>Internal error while preparing the scene.</source>
        <translation>Interner Fehler beim Vorbereiten der Szene.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PropertiesDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="386"/>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="391"/>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="392"/>
        <source>Render:</source>
        <translation>Rendern:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="393"/>
        <source>Shown</source>
        <translation>Sichtbar</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="394"/>
        <source>A hidden object stays in the scene but is not rendered</source>
        <translation>Ein ausgeblendetes Objekt bleibt in der Szene, wird aber nicht gerendert</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="395"/>
        <source>Size (W × D × H):</source>
        <translation>Größe (B × T × H):</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="396"/>
        <source>Width × depth × height in metres, as placed (before its turn)</source>
        <translation>Breite × Tiefe × Höhe in Metern, wie platziert (vor der Drehung)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="398"/>
        <source>The photo pixel the centre of the object&apos;s base stands on</source>
        <translation>Der Fotopixel, auf dem die Mitte der Standfläche des Objekts steht</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="403"/>
        <source>Surface:</source>
        <translation>Fläche:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="404"/>
        <source>Finish:</source>
        <translation>Oberfläche:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="405"/>
        <source>Roughness:</source>
        <translation>Rauheit:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="406"/>
        <location filename="../app/studio/docks.cpp" line="418"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="407"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="408"/>
        <source>Diffuse</source>
        <translation>Matt (diffus)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="408"/>
        <location filename="../app/studio/docks.cpp" line="413"/>
        <source>Glossy</source>
        <translation>Glänzend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="408"/>
        <location filename="../app/studio/docks.cpp" line="413"/>
        <source>Mirror</source>
        <translation>Spiegel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="408"/>
        <source>Metal</source>
        <translation>Metall</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>Glass</source>
        <translation>Glas</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>Frosted glass</source>
        <translation>Milchglas</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>Emissive</source>
        <translation>Leuchtend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>From the file</source>
        <translation>Aus der Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="411"/>
        <source>Reflectance of the object&apos;s surface</source>
        <translation>Reflexionsgrad der Objektoberfläche</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="397"/>
        <source>Base (px):</source>
        <translation>Fußpunkt (px):</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="83"/>
        <source>Floor</source>
        <translation>Boden</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="84"/>
        <source>Ceiling</source>
        <translation>Decke</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="85"/>
        <source>Left wall</source>
        <translation>Linke Wand</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="86"/>
        <source>Right wall</source>
        <translation>Rechte Wand</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="87"/>
        <source>Back wall</source>
        <translation>Rückwand</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="88"/>
        <source>Wall behind the camera</source>
        <translation>Wand hinter der Kamera</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="92"/>
        <source>Surface %1, top</source>
        <translation>Fläche %1, oben</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="93"/>
        <source>Surface %1, sides</source>
        <translation>Fläche %1, Seiten</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="399"/>
        <location filename="../app/studio/docks.cpp" line="417"/>
        <source>Height:</source>
        <translation>Höhe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="400"/>
        <source>Turn:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="401"/>
        <source>Material:</source>
        <translation>Material:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="402"/>
        <source>Colour:</source>
        <translation>Farbe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="412"/>
        <source>&lt;b&gt;Room surface&lt;/b&gt;</source>
        <translation>&lt;b&gt;Raumfläche&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="413"/>
        <source>Matte</source>
        <translation>Matt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="415"/>
        <source>A real surface of the photo that reflects: a glossy floor, a mirror</source>
        <translation>Eine echte Fläche im Foto, die spiegelt: ein glänzender Boden, ein Spiegel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="416"/>
        <source>&lt;b&gt;New models&lt;/b&gt;</source>
        <translation>&lt;b&gt;Neue Modelle&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="420"/>
        <source>The height a model gets when its file does not state its unit (OBJ, PLY, 3DS) or states an absurd size</source>
        <translation>Die Höhe, die ein Modell erhält, wenn seine Datei keine Einheit nennt (OBJ, PLY, 3DS) oder eine absurde Größe angibt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="479"/>
        <source>No object selected</source>
        <translation>Kein Objekt ausgewählt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="486"/>
        <source>&lt;b&gt;Object %1&lt;/b&gt; (%2)</source>
        <translation>&lt;b&gt;Objekt %1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="490"/>
        <source>%1 × %2 × %3 m</source>
        <translation>%1 × %2 × %3 m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="494"/>
        <source>– (the scene is being prepared)</source>
        <translation>– (die Szene wird vorbereitet)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="538"/>
        <source>Object colour</source>
        <translation>Objektfarbe</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ResponseCurveView</name>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="63"/>
        <source>code (up: stops above mid-grey)</source>
        <translation>Code (nach oben: Blendenstufen über Mittelgrau)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ResponseDock</name>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="124"/>
        <source>Uses the standard sRGB curve, as chosen in the list.</source>
        <translation>Verwendet die übliche sRGB-Kurve, wie in der Liste gewählt.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="126"/>
        <source>Uses a straight (linear) curve, as chosen in the list: the photo&apos;s values are read as light directly.</source>
        <translation>Verwendet eine gerade (lineare) Kurve, wie in der Liste gewählt: die Werte des Fotos werden direkt als Licht gelesen.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="129"/>
        <source>Uses the curve given in the scene file.</source>
        <translation>Verwendet die Kurve aus der Szenendatei.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="122"/>
        <source>The photo already holds light values (EXR/HDR): it needs no curve.</source>
        <translation>Das Foto enthält bereits Lichtwerte (EXR/HDR): es braucht keine Kurve.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="132"/>
        <source>Kept the standard sRGB curve: the photo does not show enough to estimate its own tone curve.</source>
        <translation>Die übliche sRGB-Kurve wurde beibehalten: das Foto zeigt zu wenig, um seine eigene Tonwertkurve zu schätzen.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="137"/>
        <source>Kept the standard sRGB curve: the room&apos;s lighting explains the photo better with it than with the curve estimated from the photo.</source>
        <translation>Die übliche sRGB-Kurve wurde beibehalten: die Beleuchtung des Raums erklärt das Foto mit ihr besser als mit der aus dem Foto geschätzten Kurve.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="141"/>
        <source>Kept the standard sRGB curve: the photo&apos;s noise does not show a different tone curve clearly.</source>
        <translation>Die übliche sRGB-Kurve wurde beibehalten: das Rauschen des Fotos zeigt keine andere Tonwertkurve deutlich.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="144"/>
        <source>Kept the standard sRGB curve: the photo&apos;s edges do not show a different tone curve clearly.</source>
        <translation>Die übliche sRGB-Kurve wurde beibehalten: die Kanten des Fotos zeigen keine andere Tonwertkurve deutlich.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="147"/>
        <source>Uses the tone curve estimated from the photo&apos;s noise; it differs from the standard sRGB curve (dashed).</source>
        <translation>Verwendet die aus dem Rauschen des Fotos geschätzte Tonwertkurve; sie weicht von der üblichen sRGB-Kurve (gestrichelt) ab.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="150"/>
        <source>Uses the tone curve estimated from the photo&apos;s edges; it differs from the standard sRGB curve (dashed).</source>
        <translation>Verwendet die aus den Kanten des Fotos geschätzte Tonwertkurve; sie weicht von der üblichen sRGB-Kurve (gestrichelt) ab.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="160"/>
        <source>If the inserted objects look too bright or too flat against the room, choose sRGB in the list above and compare.</source>
        <translation>Wirken die eingefügten Objekte neben dem Raum zu hell oder zu flach, wählen Sie oben in der Liste sRGB und vergleichen Sie.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="163"/>
        <source>If the photo was edited, or comes from a phone with strong contrast, its curve may still differ: choose Linear in the list above (it reads the photo&apos;s contrast as softer) and compare the objects&apos; shading.</source>
        <translation>Wurde das Foto bearbeitet oder stammt es von einem Handy mit starkem Kontrast, kann seine Kurve trotzdem abweichen: wählen Sie oben in der Liste Linear (es liest den Kontrast des Fotos weicher) und vergleichen Sie die Schattierung der Objekte.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="173"/>
        <source>Curve: %1</source>
        <translation>Kurve: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="176"/>
        <source>Estimated from the photo&apos;s noise (%1 levels) in %2 ms.</source>
        <translation>Aus dem Rauschen des Fotos geschätzt (%1 Stufen) in %2 ms.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="180"/>
        <source>Estimated from %1 edges in %2 ms.</source>
        <translation>Aus %1 Kanten geschätzt in %2 ms.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="277"/>
        <source>Camera Response</source>
        <translation>Kamerakennlinie</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="278"/>
        <source>Auto (estimated from the photo)</source>
        <translation>Automatisch (aus dem Foto geschätzt)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="279"/>
        <source>sRGB</source>
        <translation>sRGB</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="280"/>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="281"/>
        <source>Explicit (from the scene file)</source>
        <translation>Explizit (aus der Szenendatei)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="282"/>
        <source>How the photo&apos;s pixel values map to light (camera.response)</source>
        <translation>Wie die Pixelwerte des Fotos auf Licht abgebildet werden (camera.response)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="284"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="285"/>
        <source>The curve&apos;s parameters and what the estimate measured</source>
        <translation>Die Parameter der Kurve und was die Schätzung gemessen hat</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="310"/>
        <source>Preparing the scene...</source>
        <translation>Die Szene wird vorbereitet...</translation>
    </message>
    <message>
        <source>
Estimated from the photo&apos;s noise (%1 levels) in %2 ms.</source>
        <translation type="vanished">
Aus dem Rauschen des Fotos geschätzt (%1 Stufen) in %2 ms.</translation>
    </message>
    <message>
        <source>
Estimated from %1 edges in %2 ms.</source>
        <translation type="vanished">
Aus %1 Kanten in %2 ms geschätzt.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::SceneTreeDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="72"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="73"/>
        <source>cube</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="98"/>
        <source>table top or step</source>
        <translation>Tischplatte oder Stufe</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="99"/>
        <source>box</source>
        <translation>Quader</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="100"/>
        <source>stairs</source>
        <translation>Treppe</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="156"/>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="157"/>
        <source>Item</source>
        <translation>Element</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="157"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="161"/>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="164"/>
        <source>%1 × %2 m, %3 m high</source>
        <translation>%1 × %2 m, %3 m hoch</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="169"/>
        <source>back wall given</source>
        <translation>Rückwand vorgegeben</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="169"/>
        <source>estimated</source>
        <translation>geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="172"/>
        <source>Lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="177"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="178"/>
        <source>outline on the photo</source>
        <translation>Umriss im Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="178"/>
        <source>rectangle in 3D</source>
        <translation>Rechteck im Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="192"/>
        <source>Shafts</source>
        <translation>Sonnenstrahlen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="192"/>
        <source>Shaft %1</source>
        <translation>Sonnenstrahl %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="193"/>
        <source>sunlit patch and its window</source>
        <translation>Sonnenfleck und sein Fenster</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="194"/>
        <source>Surfaces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="194"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="196"/>
        <source>Occluders</source>
        <translation>Verdecker</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="196"/>
        <source>Occluder %1</source>
        <translation>Verdecker %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="197"/>
        <source>%1 strokes in front, %2 behind</source>
        <translation>%1 Striche davor, %2 dahinter</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="201"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="206"/>
        <source>hidden: %1</source>
        <translation>ausgeblendet: %1</translation>
    </message>
    <message>
        <source>Object %1</source>
        <translation type="vanished">Objekt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="204"/>
        <source>%1, %2 m</source>
        <translation>%1, %2 m</translation>
    </message>
</context>
<context>
    <name>inlay::studio::StageText</name>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="17"/>
        <source>photo</source>
        <translation>Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="18"/>
        <source>response</source>
        <translation>Kennlinie</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="19"/>
        <source>working copy</source>
        <translation>Arbeitskopie</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="20"/>
        <source>camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="21"/>
        <source>layout</source>
        <translation>Raumaufteilung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="22"/>
        <source>occluders</source>
        <translation>Verdecker</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="23"/>
        <source>surfaces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="24"/>
        <source>room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="25"/>
        <source>lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="26"/>
        <source>shafts</source>
        <translation>Sonnenstrahlen</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="27"/>
        <source>lighting</source>
        <translation>Beleuchtung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="28"/>
        <source>vignetting</source>
        <translation>Vignettierung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="29"/>
        <source>sun ratio</source>
        <translation>Sonnenverhältnis</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="30"/>
        <source>refine</source>
        <translation>Verfeinerung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="31"/>
        <source>lighting refit</source>
        <translation>Neuanpassung der Beleuchtung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="36"/>
        <source>response check</source>
        <translation>Prüfung der Kamerakennlinie</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="32"/>
        <source>photo size</source>
        <translation>Fotogröße</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="33"/>
        <source>render scene</source>
        <translation>Render-Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="34"/>
        <source>objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="35"/>
        <source>grain</source>
        <translation>Körnung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="38"/>
        <source>gather</source>
        <translation>Sammeln</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="39"/>
        <source>light fit</source>
        <translation>Lichtanpassung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="40"/>
        <source>unseen patches</source>
        <translation>unsichtbare Flächen</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="41"/>
        <source>retinex</source>
        <translation>Retinex</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="42"/>
        <source>decomposition</source>
        <translation>Zerlegung</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="43"/>
        <source>direct light</source>
        <translation>direktes Licht</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="44"/>
        <source>fit pixels</source>
        <translation>Anpassungspixel</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="45"/>
        <source>per-pixel albedo</source>
        <translation>Albedo je Pixel</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="47"/>
        <source>both candidates, side by side</source>
        <translation>beide Kandidaten, nebeneinander</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="48"/>
        <source>both candidates, one after the other</source>
        <translation>beide Kandidaten, nacheinander</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="50"/>
        <source>both copies, side by side</source>
        <translation>beide Kopien, nebeneinander</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="51"/>
        <source>both copies, one after the other</source>
        <translation>beide Kopien, nacheinander</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="61"/>
        <source>copy, curve: %1</source>
        <translation>Kopie, Kurve: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="62"/>
        <source>copy, sRGB: %1</source>
        <translation>Kopie, sRGB: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="63"/>
        <source>sRGB: %1</source>
        <translation>mit sRGB: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="82"/>
        <source>; CPU s: %1</source>
        <translation>; CPU-s: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="91"/>
        <source>%1: skipped, %2</source>
        <translation>%1: übersprungen, %2</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="93"/>
        <source>%1: %2 s, CPU %3 s</source>
        <translation>%1: %2 s, CPU %3 s</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="100"/>
        <source>at %1 x %2 px</source>
        <translation>bei %1 x %2 px</translation>
    </message>
</context>
<context>
    <name>inlay::studio::StepsDock</name>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="101"/>
        <source>no photo yet</source>
        <translation>noch kein Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="101"/>
        <source>Open Photo…</source>
        <translation>Foto öffnen…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="102"/>
        <source>the box is yours</source>
        <translation>Ihre eigene Box</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="104"/>
        <source>estimated: check that the back wall&apos;s corners sit on the room&apos;s corners</source>
        <translation>geschätzt: prüfen, ob die Ecken der Rückwand auf denen des Raums sitzen</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="105"/>
        <source>Accept the Box</source>
        <translation>Box übernehmen</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="106"/>
        <source>being estimated…</source>
        <translation>wird geschätzt…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="108"/>
        <source>not found: drag the back wall&apos;s corners onto the room&apos;s corners</source>
        <translation>nicht gefunden: die Ecken der Rückwand auf die des Raums ziehen</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="113"/>
        <source>none: objects are lit by gathered light only</source>
        <translation>keine: Objekte werden nur vom gesammelten Licht beleuchtet</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="113"/>
        <source>Outline a Light</source>
        <translation>Licht umreißen</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/steps_dock.cpp" line="115"/>
        <source>%n outlined</source>
        <translation>
            <numerusform>%n umrissen</numerusform>
            <numerusform>%n umrissen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="119"/>
        <source>none yet (or drag one from the Library)</source>
        <translation>noch keine (oder eines aus der Bibliothek ziehen)</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="119"/>
        <source>Insert Model…</source>
        <translation>Modell einfügen…</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/steps_dock.cpp" line="121"/>
        <source>%n in the photo</source>
        <translation>
            <numerusform>%n im Foto</numerusform>
            <numerusform>%n im Foto</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="124"/>
        <source>not yet</source>
        <translation>noch nicht</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="124"/>
        <source>Render Final Image…</source>
        <translation>Endgültiges Bild rendern…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="126"/>
        <source>written to %1</source>
        <translation>nach %1 geschrieben</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="156"/>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="157"/>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="157"/>
        <source>Lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="157"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="157"/>
        <source>Export</source>
        <translation>Export</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Viewport</name>
    <message>
        <location filename="../app/studio/viewport.cpp" line="322"/>
        <source>Drag an object or a corner of the back wall.</source>
        <translation>Ziehen Sie ein Objekt oder eine Ecke der Rückwand.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="324"/>
        <source>Click around a light; click the first point (or press Enter) to close.</source>
        <translation>Klicken Sie um eine Lampe herum; ein Klick auf den ersten Punkt (oder Eingabe) schließt den Umriss.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="326"/>
        <source>Now drag a box around the window the sunlight comes through.</source>
        <translation>Ziehen Sie nun einen Rahmen um das Fenster, durch das die Sonne scheint.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="327"/>
        <source>Drag a box around the patch of sunlight.</source>
        <translation>Ziehen Sie einen Rahmen um den Sonnenfleck.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="330"/>
        <source>Click the floor straight below the first point of the outline.</source>
        <translation>Klicken Sie auf den Boden genau unter dem ersten Punkt des Umrisses.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="331"/>
        <source>Click around the top of a table or step; click the first point to close.</source>
        <translation>Klicken Sie um eine Tischplatte oder Stufe herum; ein Klick auf den ersten Punkt schließt den Umriss.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="333"/>
        <source>Left drag over the thing in front, right drag over what is behind it; Enter starts another occluder.</source>
        <translation>Mit links über das ziehen, was davor ist, mit rechts über das, was dahinter ist; Eingabe beginnt einen weiteren Verdecker.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="339"/>
        <source>Drag along an edge that runs in the %1 direction (keys X, Y, Z choose it).</source>
        <translation>Ziehen Sie entlang einer Kante in %1-Richtung (die Tasten X, Y, Z wählen sie).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="341"/>
        <source>Now drag along a second edge in the %1 direction.</source>
        <translation>Ziehen Sie nun entlang einer zweiten Kante in %1-Richtung.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="437"/>
        <source>Back wall (yours)</source>
        <translation>Rückwand (Ihre)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="437"/>
        <source>Back wall (estimated)</source>
        <translation>Rückwand (geschätzt)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="525"/>
        <source>%1 px</source>
        <translation>%1 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="565"/>
        <source>%1: %2 px</source>
        <translation>%1: %2 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="598"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="612"/>
        <source>Shaft %1</source>
        <translation>Sonnenstrahl %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="627"/>
        <source>Surface %1</source>
        <translation>Fläche %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="688"/>
        <source>%1 hidden</source>
        <translation>%1 ausgeblendet</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="781"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="783"/>
        <source>The scene could not be prepared: %1</source>
        <translation>Die Szene konnte nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="787"/>
        <source>Open a scene or a photo (File menu).</source>
        <translation>Öffnen Sie eine Szene oder ein Foto (Menü Datei).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="790"/>
        <source>Before: the photo without objects</source>
        <translation>Vorher: das Foto ohne Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="822"/>
        <source>Vanishing points: x %1, y %2, z %3 (confidence)</source>
        <translation>Fluchtpunkte: x %1, y %2, z %3 (Konfidenz)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="826"/>
        <source>Focal length %1 px (%2–%3 px)</source>
        <translation>Brennweite %1 px (%2–%3 px)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="837"/>
        <source>The whole warnings: the Log tab (View ▸ Log); this text: View ▸ Vanishing Lines and Confidence</source>
        <translation>Die ganzen Warnungen: der Reiter Protokoll (Ansicht ▸ Protokoll); dieser Text: Ansicht ▸ Fluchtlinien und Konfidenz</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="892"/>
        <source>Before</source>
        <translation>Vorher</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="892"/>
        <source>After</source>
        <translation>Nachher</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="979"/>
        <source>the left wall</source>
        <translation>der linken Wand</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="980"/>
        <source>the right wall</source>
        <translation>der rechten Wand</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="981"/>
        <source>the back wall</source>
        <translation>der Rückwand</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="982"/>
        <source>the wall behind the camera</source>
        <translation>der Wand hinter der Kamera</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="983"/>
        <source>Its back against %1 (hold Shift to place it freely).</source>
        <translation>Mit dem Rücken an %1 (Umschalt gedrückt halten: frei platzieren).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1004"/>
        <source>Turned %1°</source>
        <translation>Gedreht auf %1°</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1014"/>
        <source>Height %1 m</source>
        <translation>Höhe %1 m</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1047"/>
        <source>An outline needs at least three points.</source>
        <translation>Ein Umriss braucht mindestens drei Punkte.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="972"/>
        <location filename="../app/studio/viewport.cpp" line="1370"/>
        <source>Cannot place the object here: %1</source>
        <translation>Das Objekt kann hier nicht stehen: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1303"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Jede Linie muss mindestens zwei Pixel lang sein.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/studio/main.cpp" line="81"/>
        <source>Insert synthetic objects into a photograph.</source>
        <translation>Synthetische Objekte in ein Foto einfügen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="86"/>
        <source>A scene file (.json) or a photo; none: the example.</source>
        <translation>Eine Szenendatei (.json) oder ein Foto; ohne Angabe: das Beispiel.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="90"/>
        <source>Grab the window to &lt;file&gt; once rendered, then exit.</source>
        <translation>Das Fenster nach dem Rendern in &lt;file&gt; speichern, dann beenden.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="94"/>
        <source>Samples per pixel to wait for (default 4).</source>
        <translation>Abzuwartende Samples pro Pixel (Vorgabe 4).</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="98"/>
        <source>Instead: render seconds of the shown frame to wait for.</source>
        <translation>Stattdessen: Render-Sekunden des angezeigten Bildes, auf die gewartet wird.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="102"/>
        <source>Show the Log dock across the bottom of the window.</source>
        <translation>Das Protokoll über die ganze Breite unten im Fenster zeigen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="105"/>
        <source>Restore unsaved work left by a crash without asking.</source>
        <translation>Ungesicherte Arbeit nach einem Absturz ohne Nachfrage wiederherstellen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="108"/>
        <source>Insert the model &lt;file&gt; into the scene once it is prepared.</source>
        <translation>Das Modell &lt;file&gt; in die Szene einfügen, sobald sie vorbereitet ist.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="127"/>
        <source>Give at most one file.</source>
        <translation>Geben Sie höchstens eine Datei an.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="134"/>
        <location filename="../app/studio/main.cpp" line="142"/>
        <source>expected a number &gt;= 0</source>
        <translation>eine Zahl &gt;= 0 erwartet</translation>
    </message>
</context>
</TS>
