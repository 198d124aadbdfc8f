<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>inlay::studio::Document</name>
    <message>
        <location filename="../app/studio/document.cpp" line="238"/>
        <location filename="../app/studio/document.cpp" line="252"/>
        <source>Preparation was cancelled.</source>
        <translation>Die Vorbereitung wurde abgebrochen.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="273"/>
        <location filename="../app/studio/document.cpp" line="363"/>
        <source>There is no object %1.</source>
        <translation>Es gibt kein Objekt %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="274"/>
        <location filename="../app/studio/document.cpp" line="341"/>
        <location filename="../app/studio/document.cpp" line="364"/>
        <source>The scene is still being prepared.</source>
        <translation>Die Szene wird noch vorbereitet.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="275"/>
        <location filename="../app/studio/document.cpp" line="342"/>
        <location filename="../app/studio/document.cpp" line="365"/>
        <source>The scene could not be prepared.</source>
        <translation>Die Szene konnte nicht vorbereitet werden.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="277"/>
        <source>The position is not a number.</source>
        <translation>Die Position ist keine Zahl.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="279"/>
        <location filename="../app/studio/document.cpp" line="344"/>
        <source>The height must be greater than zero.</source>
        <translation>Die Höhe muss größer als null sein.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="301"/>
        <source>Move object %1</source>
        <translation>Objekt %1 verschieben</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="308"/>
        <source>Change height of object %1</source>
        <translation>Höhe von Objekt %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="315"/>
        <source>Turn object %1</source>
        <translation>Objekt %1 drehen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="322"/>
        <source>Change material of object %1</source>
        <translation>Material von Objekt %1 ändern</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="354"/>
        <source>Insert object %1</source>
        <translation>Objekt %1 einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="368"/>
        <source>Delete object %1</source>
        <translation>Objekt %1 löschen</translation>
    </message>
</context>
<context>
    <name>inlay::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="75"/>
        <source>Reading the photo</source>
        <translation>Foto wird gelesen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="76"/>
        <source>Estimating the camera</source>
        <translation>Kamera wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="77"/>
        <source>Fitting the room</source>
        <translation>Raum wird angepasst</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="78"/>
        <source>Estimating the lighting</source>
        <translation>Beleuchtung wird geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="79"/>
        <source>Placing the objects</source>
        <translation>Objekte werden platziert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="107"/>
        <source>Samples per pixel of the shown composite</source>
        <translation>Samples pro Pixel des angezeigten Komposits</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="108"/>
        <source>Estimated error (RMSE in sRGB) where the objects change the photo</source>
        <translation>Geschätzter Fehler (RMSE in sRGB), wo die Objekte das Foto verändern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="109"/>
        <source>Render time since the last change</source>
        <translation>Renderzeit seit der letzten Änderung</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="110"/>
        <source>Zoom</source>
        <translation>Zoom</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="111"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="122"/>
        <source>Preparing the scene: %1…</source>
        <translation>Szene wird vorbereitet: %1 …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="152"/>
        <source>&amp;Open Scene…</source>
        <translation>Szene &amp;öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="154"/>
        <source>Open a scene file (.json)</source>
        <translation>Eine Szenendatei (.json) öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="157"/>
        <source>Open &amp;Photo…</source>
        <translation>&amp;Foto öffnen …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="159"/>
        <source>Start a new scene from a photo</source>
        <translation>Eine neue Szene aus einem Foto beginnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="162"/>
        <source>Open &amp;Example</source>
        <translation>&amp;Beispiel öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="165"/>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="169"/>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="173"/>
        <source>&amp;Export Composite…</source>
        <translation>Komposit &amp;exportieren …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="175"/>
        <source>Write the current composite as PNG, JPEG, TIFF or EXR</source>
        <translation>Das aktuelle Komposit als PNG, JPEG, TIFF oder EXR schreiben</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="178"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="182"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="185"/>
        <source>&amp;Redo</source>
        <translation>Wi&amp;ederholen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="189"/>
        <source>Insert &amp;Sphere</source>
        <translation>&amp;Kugel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="190"/>
        <source>Stand a sphere on the floor in the middle of the photo</source>
        <translation>Eine Kugel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="193"/>
        <source>Insert &amp;Cube</source>
        <translation>&amp;Würfel einfügen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="194"/>
        <source>Stand a cube on the floor in the middle of the photo</source>
        <translation>Einen Würfel in der Bildmitte auf den Boden stellen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="197"/>
        <source>&amp;Delete Object</source>
        <translation>Objekt &amp;löschen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="201"/>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="204"/>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="207"/>
        <source>&amp;Fit to Window</source>
        <translation>An &amp;Fenster anpassen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="210"/>
        <source>&amp;Before (Photo Only)</source>
        <translation>&amp;Vorher (nur Foto)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="213"/>
        <source>Toggle between the photo and the composite with the objects</source>
        <translation>Zwischen dem Foto und dem Komposit mit den Objekten umschalten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="216"/>
        <source>&amp;About Inlay</source>
        <translation>&amp;Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="221"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="225"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="235"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="243"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="253"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="257"/>
        <source>System Default</source>
        <translation>Systemvorgabe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="267"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="270"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="288"/>
        <location filename="../app/studio/main_window.cpp" line="297"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="288"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="289"/>
        <location filename="../app/studio/main_window.cpp" line="587"/>
        <source>Inlay</source>
        <translation>Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="309"/>
        <source>The scene could not be prepared</source>
        <translation>Die Szene konnte nicht vorbereitet werden</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/main_window.cpp" line="316"/>
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (und %n weiterer Hinweis)</numerusform>
            <numerusform>%1 (und %n weitere Hinweise)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="338"/>
        <source>– spp</source>
        <translation>– spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="339"/>
        <source>error –</source>
        <translation>Fehler –</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="340"/>
        <source>– s</source>
        <translation>– s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="344"/>
        <source>preview 1/%1</source>
        <translation>Vorschau 1/%1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="345"/>
        <source>%1 spp, done</source>
        <translation>%1 spp, fertig</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="346"/>
        <source>%1 spp</source>
        <translation>%1 spp</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="347"/>
        <source>error %1</source>
        <translation>Fehler %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="348"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="358"/>
        <source>%1 (new scene)</source>
        <translation>%1 (neue Szene)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="361"/>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="362"/>
        <source>%1[*] — Inlay</source>
        <translation>%1[*] — Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="381"/>
        <source>Cannot open</source>
        <translation>Öffnen nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="381"/>
        <source>%1: no such file</source>
        <translation>%1: Datei nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="387"/>
        <source>Cannot open the scene</source>
        <translation>Die Szene kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="406"/>
        <location filename="../app/studio/main_window.cpp" line="416"/>
        <source>Cannot open the example</source>
        <translation>Das Beispiel kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="406"/>
        <source>The example scene is not installed.</source>
        <translation>Die Beispielszene ist nicht installiert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="416"/>
        <source>Cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="426"/>
        <source>Open Scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="427"/>
        <source>Inlay scenes (*.json);;All files (*)</source>
        <translation>Inlay-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="434"/>
        <source>Open Photo</source>
        <translation>Foto öffnen</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="435"/>
        <source>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)</source>
        <translation>Fotos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="442"/>
        <source>Cannot save the scene</source>
        <translation>Die Szene kann nicht gespeichert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="446"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="461"/>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="462"/>
        <source>Inlay scenes (*.json)</source>
        <translation>Inlay-Szenen (*.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="470"/>
        <location filename="../app/studio/main_window.cpp" line="491"/>
        <source>Nothing to export</source>
        <translation>Nichts zu exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="470"/>
        <location filename="../app/studio/main_window.cpp" line="491"/>
        <source>The composite has not been rendered yet.</source>
        <translation>Das Komposit wurde noch nicht gerendert.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="474"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="474"/>
        <source>JPEG image (*.jpg *.jpeg)</source>
        <translation>JPEG-Bild (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="475"/>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>TIFF-Bild (*.tif *.tiff)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="475"/>
        <source>OpenEXR, linear (*.exr)</source>
        <translation>OpenEXR, linear (*.exr)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="476"/>
        <source>Export Composite</source>
        <translation>Komposit exportieren</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="496"/>
        <source>Cannot export the composite</source>
        <translation>Das Komposit kann nicht exportiert werden</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="499"/>
        <source>Exported %1 (%2 spp)</source>
        <translation>%1 exportiert (%2 spp)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="523"/>
        <source>About Inlay</source>
        <translation>Über Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="524"/>
        <source>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Inserts synthetic objects into an ordinary photograph: a box room is fitted to the photo, its lights and reflectance are estimated, and a path tracer renders the objects into it (after Karsch et al., 2011).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Fügt synthetische Objekte in ein gewöhnliches Foto ein: Ein Quaderraum wird an das Foto angepasst, seine Lichter und Reflexionsgrade werden geschätzt, und ein Pfadverfolger rendert die Objekte hinein (nach Karsch et al., 2011).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="533"/>
        <source>There is no floor in the middle of the photo to stand an object on.</source>
        <translation>In der Bildmitte gibt es keinen Boden, auf dem ein Objekt stehen kann.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="581"/>
        <source>The language changes when Inlay is started again.</source>
        <translation>Die Sprache wechselt beim nächsten Start von Inlay.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="587"/>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>Die Szene hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PrepareWorker</name>
    <message>
        <location filename="../app/studio/prepare_worker.cpp" line="43"/>
        <source>Internal error while preparing the scene.</source>
        <translation>Interner Fehler beim Vorbereiten der Szene.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PropertiesDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="122"/>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="134"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="142"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="146"/>
        <source>Diffuse</source>
        <translation>Matt (diffus)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="147"/>
        <source>Glossy</source>
        <translation>Glänzend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="148"/>
        <source>Mirror</source>
        <translation>Spiegel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="149"/>
        <source>Glass</source>
        <translation>Glas</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="150"/>
        <source>Emissive</source>
        <translation>Leuchtend</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="151"/>
        <source>From the file</source>
        <translation>Aus der Datei</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="154"/>
        <source>Reflectance of the object&apos;s surface</source>
        <translation>Reflexionsgrad der Objektoberfläche</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="157"/>
        <source>Base (px):</source>
        <translation>Fußpunkt (px):</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="158"/>
        <source>Height:</source>
        <translation>Höhe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="159"/>
        <source>Turn:</source>
        <translation>Drehung:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="160"/>
        <source>Material:</source>
        <translation>Material:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="161"/>
        <source>Colour:</source>
        <translation>Farbe:</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="180"/>
        <source>No object selected</source>
        <translation>Kein Objekt ausgewählt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="185"/>
        <source>&lt;b&gt;Object %1&lt;/b&gt; (%2)</source>
        <translation>&lt;b&gt;Objekt %1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="230"/>
        <source>Object colour</source>
        <translation>Objektfarbe</translation>
    </message>
</context>
<context>
    <name>inlay::studio::SceneTreeDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="25"/>
        <source>sphere</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="26"/>
        <source>cube</source>
        <translation>Würfel</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="40"/>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="42"/>
        <source>Item</source>
        <translation>Element</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="42"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="69"/>
        <source>Room</source>
        <translation>Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="72"/>
        <source>%1 × %2 m, %3 m high</source>
        <translation>%1 × %2 m, %3 m hoch</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="77"/>
        <source>back wall given</source>
        <translation>Rückwand vorgegeben</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="77"/>
        <source>estimated</source>
        <translation>geschätzt</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="80"/>
        <source>Lights</source>
        <translation>Lichter</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="83"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="84"/>
        <source>outline on the photo</source>
        <translation>Umriss im Foto</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="85"/>
        <source>rectangle in 3D</source>
        <translation>Rechteck im Raum</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="88"/>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="92"/>
        <source>Object %1</source>
        <translation>Objekt %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="93"/>
        <source>%1, %2 m</source>
        <translation>%1, %2 m</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Viewport</name>
    <message>
        <location filename="../app/studio/viewport.cpp" line="225"/>
        <source>Light %1</source>
        <translation>Licht %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="276"/>
        <source>Preparing the scene…</source>
        <translation>Szene wird vorbereitet …</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="279"/>
        <source>The scene could not be prepared: %1</source>
        <translation>Die Szene konnte nicht vorbereitet werden: %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="283"/>
        <source>Open a scene or a photo (File menu).</source>
        <translation>Öffnen Sie eine Szene oder ein Foto (Menü Datei).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="286"/>
        <source>Before: the photo without objects</source>
        <translation>Vorher: das Foto ohne Objekte</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="338"/>
        <location filename="../app/studio/viewport.cpp" line="381"/>
        <source>Cannot place the object here: %1</source>
        <translation>Das Objekt kann hier nicht stehen: %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/studio/main.cpp" line="46"/>
        <source>Insert synthetic objects into a photograph.</source>
        <translation>Synthetische Objekte in ein Foto einfügen.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="51"/>
        <source>A scene file (.json) or a photo; none: the example.</source>
        <translation>Eine Szenendatei (.json) oder ein Foto; ohne Angabe: das Beispiel.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="55"/>
        <source>Grab the window to &lt;file&gt; once rendered, then exit.</source>
        <translation>Das Fenster nach dem Rendern in &lt;file&gt; speichern, dann beenden.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="59"/>
        <source>Samples per pixel to wait for (default 4).</source>
        <translation>Abzuwartende Samples pro Pixel (Vorgabe 4).</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="74"/>
        <source>Give at most one file.</source>
        <translation>Geben Sie höchstens eine Datei an.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="81"/>
        <source>expected a number &gt;= 0</source>
        <translation>eine Zahl &gt;= 0 erwartet</translation>
    </message>
</context>
</TS>
