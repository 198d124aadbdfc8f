<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>inlay::studio::Autosaver</name>
    <message>
        <location filename="../app/studio/autosave.cpp" line="60"/>
        <source>%1: cannot take the lock</source>
        <translation>%1 : impossible de prendre le verrou</translation>
    </message>
    <message>
        <location filename="../app/studio/autosave.cpp" line="102"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1 : écriture impossible (%2)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Document</name>
    <message>
        <location filename="../app/studio/document.cpp" line="307"/>
        <location filename="../app/studio/document.cpp" line="337"/>
        <source>Preparation was cancelled.</source>
        <translation>La préparation a été annulée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="393"/>
        <location filename="../app/studio/document.cpp" line="827"/>
        <location filename="../app/studio/document.cpp" line="1015"/>
        <location filename="../app/studio/document.cpp" line="1074"/>
        <source>The position is not a number.</source>
        <translation>La position n&apos;est pas un nombre.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="395"/>
        <location filename="../app/studio/document.cpp" line="525"/>
        <location filename="../app/studio/document.cpp" line="542"/>
        <source>The height must be greater than zero.</source>
        <translation>La hauteur doit être supérieure à zéro.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="417"/>
        <location filename="../app/studio/document.cpp" line="451"/>
        <source>Move object %1</source>
        <translation>Déplacer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="425"/>
        <source>Change height of object %1</source>
        <translation>Changer la hauteur de l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="431"/>
        <location filename="../app/studio/document.cpp" line="444"/>
        <source>The turn is not a number.</source>
        <translation>La rotation n&apos;est pas un nombre.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="437"/>
        <source>Turn object %1</source>
        <translation>Tourner l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="496"/>
        <source>Change material of object %1</source>
        <translation>Changer le matériau de l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="511"/>
        <source>There is no object %1.</source>
        <translation>Il n&apos;y a pas d&apos;objet %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="513"/>
        <source>The scene is still being prepared.</source>
        <translation>La scène est encore en préparation.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="514"/>
        <source>The scene could not be prepared.</source>
        <translation>La scène n&apos;a pas pu être préparée.</translation>
    </message>
    <message>
        <source>Insert object %1</source>
        <translation type="vanished">Insérer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="540"/>
        <source>The model has no triangles.</source>
        <translation>Le modèle n&apos;a aucun triangle.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="548"/>
        <source>object %1</source>
        <translation>objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="551"/>
        <source>Insert %1</source>
        <translation>Insérer %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="569"/>
        <source>Duplicate %1</source>
        <translation>Dupliquer %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="619"/>
        <source>Rename %1</source>
        <translation>Renommer %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="627"/>
        <source>Hide %1</source>
        <translation>Masquer %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="627"/>
        <source>Show %1</source>
        <translation>Afficher %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="635"/>
        <location filename="../app/studio/document.cpp" line="652"/>
        <source>sphere</source>
        <translation>sphère</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="636"/>
        <location filename="../app/studio/document.cpp" line="653"/>
        <source>cube</source>
        <translation>cube</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="691"/>
        <source>Delete object %1</source>
        <translation>Supprimer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="791"/>
        <source>Open a photo first.</source>
        <translation>Ouvrez d&apos;abord une photo.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="811"/>
        <source>There is no estimated box yet.</source>
        <translation>Il n&apos;y a pas encore de pièce estimée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="817"/>
        <source>Accept the estimated box</source>
        <translation>Accepter la pièce estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="823"/>
        <source>There is no such corner of the back wall.</source>
        <translation>Ce coin du mur du fond n&apos;existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="834"/>
        <source>Move a corner of the back wall</source>
        <translation>Déplacer un coin du mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="841"/>
        <source>Estimate the box again</source>
        <translation>Estimer à nouveau la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="846"/>
        <source>A light&apos;s outline needs at least three points around an area.</source>
        <translation>Le contour d&apos;une lampe doit compter au moins trois points entourant une surface.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="855"/>
        <source>Outline light %1</source>
        <translation>Détourer la lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="861"/>
        <location filename="../app/studio/document.cpp" line="1037"/>
        <source>Each box of a shaft must be at least two pixels wide and high.</source>
        <translation>Chaque cadre d&apos;un rayon de soleil doit mesurer au moins deux pixels de large et de haut.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="870"/>
        <source>Add shaft %1</source>
        <translation>Ajouter le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="877"/>
        <source>A surface&apos;s outline needs at least three points around an area.</source>
        <translation>Le contour d&apos;une surface doit compter au moins trois points entourant une aire.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="887"/>
        <source>Add surface %1</source>
        <translation>Ajouter la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="897"/>
        <source>An occluder needs a stroke over the thing in front and one over what is behind it.</source>
        <translation>Un masque d&apos;avant-plan demande un trait sur ce qui est devant et un sur ce qui est derrière.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="903"/>
        <source>Add occluder %1</source>
        <translation>Ajouter le masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="909"/>
        <source>There is no such occluder, or the stroke is empty.</source>
        <translation>Ce masque d&apos;avant-plan n&apos;existe pas, ou le trait est vide.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="916"/>
        <source>Add a stroke to occluder %1</source>
        <translation>Ajouter un trait au masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="927"/>
        <source>There is no such mark.</source>
        <translation>Ce repère n&apos;existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="935"/>
        <source>Delete light %1</source>
        <translation>Supprimer la lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="936"/>
        <source>Delete shaft %1</source>
        <translation>Supprimer le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="937"/>
        <source>Delete surface %1</source>
        <translation>Supprimer la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="938"/>
        <source>Delete occluder %1</source>
        <translation>Supprimer le masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1018"/>
        <source>There is no such point.</source>
        <translation>Ce point n’existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1027"/>
        <location filename="../app/studio/document.cpp" line="1046"/>
        <source>The outline would lose its area.</source>
        <translation>Le contour perdrait sa surface.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1028"/>
        <source>Reshape light %1</source>
        <translation>Remodeler la lumière %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1038"/>
        <source>Reshape shaft %1</source>
        <translation>Remodeler le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1047"/>
        <source>Reshape surface %1</source>
        <translation>Remodeler la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1055"/>
        <source>Reshape occluder %1</source>
        <translation>Remodeler l’occultant %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1071"/>
        <source>There is no such axis.</source>
        <translation>Cet axe n’existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1076"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Chaque ligne doit mesurer au moins deux pixels.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1082"/>
        <source>The two lines lie on one line: draw two different edges.</source>
        <translation>Les deux lignes sont sur une même droite : tracez deux arêtes différentes.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1091"/>
        <source>Draw the %1 vanishing lines</source>
        <translation>Tracer les lignes de fuite %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1092"/>
        <source>Forget the %1 vanishing lines</source>
        <translation>Oublier les lignes de fuite %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1106"/>
        <source>The room has no surface %1.</source>
        <translation>La pièce n’a pas de surface %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1109"/>
        <source>Unknown material.</source>
        <translation>Matériau inconnu.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1112"/>
        <source>The roughness must lie between 0 and 1.</source>
        <translation>La rugosité doit être comprise entre 0 et 1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1118"/>
        <source>Change the material of %1</source>
        <translation>Changer le matériau de %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="1126"/>
        <source>Change the camera response</source>
        <translation>Changer la réponse de l&apos;appareil</translation>
    </message>
</context>
<context>
    <name>inlay::studio::EngineText</name>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="33"/>
        <source>empty file</source>
        <translation>fichier vide</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="34"/>
        <source>cannot open for reading</source>
        <translation>impossible de l&apos;ouvrir en lecture</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="35"/>
        <source>read failed</source>
        <translation>la lecture a échoué</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="36"/>
        <source>no triangles</source>
        <translation>aucun triangle</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="37"/>
        <source>import failed: %1</source>
        <translation>l&apos;import a échoué : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="38"/>
        <source>non-finite coordinate &apos;%1&apos;</source>
        <translation>coordonnée non finie « %1 »</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="39"/>
        <source>non-finite coordinate</source>
        <translation>coordonnée non finie</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="40"/>
        <source>malformed number &apos;%1&apos;</source>
        <translation>nombre mal formé « %1 »</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="41"/>
        <source>malformed face index &apos;%1&apos;</source>
        <translation>indice de face mal formé « %1 »</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="42"/>
        <source>face corner without a vertex index</source>
        <translation>coin de face sans indice de sommet</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="43"/>
        <source>face index 0 (OBJ indices start at 1)</source>
        <translation>indice de face 0 (les indices OBJ commencent à 1)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="44"/>
        <source>a face needs at least 3 vertices</source>
        <translation>une face demande au moins 3 sommets</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="45"/>
        <source>more than %1 triangles</source>
        <translation>plus de %1 triangles</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="46"/>
        <source>more than %1 vertices</source>
        <translation>plus de %1 sommets</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="47"/>
        <source>%1 vertices exceed the limit of %2</source>
        <translation>%1 sommets dépassent la limite de %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="48"/>
        <source>&apos;%1&apos; needs %2 numbers</source>
        <translation>« %1 » demande %2 nombres</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="49"/>
        <source>not a PLY file (missing &apos;ply&apos; magic)</source>
        <translation>pas un fichier PLY (la signature « ply » manque)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="50"/>
        <source>not a GLB file</source>
        <translation>pas un fichier GLB</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="51"/>
        <source>invalid glTF JSON</source>
        <translation>JSON glTF invalide</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="52"/>
        <source>buffer file not found: %1</source>
        <translation>fichier de tampon introuvable : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="54"/>
        <source>none given; the objects are lit by the room&apos;s gathered light only</source>
        <translation>aucune indiquée ; les objets ne sont éclairés que par la lumière réfléchie de la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="56"/>
        <source>ignored, the photo is already linear (EXR/HDR)</source>
        <translation>ignorée, la photo est déjà linéaire (EXR/HDR)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="57"/>
        <source>the estimated back wall is unusable (%1); using a 5 x 5.5 m room: give layout.back_wall_px</source>
        <translation>le mur du fond estimé est inutilisable (%1) ; une pièce de 5 x 5,5 m est utilisée : indiquez layout.back_wall_px</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="60"/>
        <source>the photo shows no clear room structure; the camera is a fallback (prior focal length, upright): give camera.vanishing_points_px for a reliable result</source>
        <translation>la photo ne montre pas nettement la structure de la pièce ; la caméra est une solution de repli (focale a priori, droite) : indiquez camera.vanishing_points_px pour un résultat fiable</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="64"/>
        <source>the photo shows no clear room structure; the camera is a fallback (default focal length, upright): give camera.vanishing_points_px for a reliable result</source>
        <translation>la photo ne montre pas nettement la structure de la pièce ; la caméra est une solution de repli (focale par défaut, droite) : indiquez camera.vanishing_points_px pour un résultat fiable</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="68"/>
        <source>strength kept as estimated: %1</source>
        <translation>intensité gardée telle qu&apos;estimée : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="69"/>
        <source>the window the sun comes through is out of view; its sky is a light of %1 x %2 m on the %3 (where the beam came from), its intensity fitted (give source_box_px, or outline the window as a light, to choose)</source>
        <translation>la fenêtre par laquelle entre le soleil est hors champ ; son ciel est une lumière de %1 x %2 m sur %3 (d&apos;où vient le faisceau), d&apos;intensité ajustée (indiquez source_box_px, ou détourez la fenêtre comme lumière, pour choisir)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="73"/>
        <source>%1&apos;s matte shows the floor under the top at %2 of %3 points, so it is a slab %4 m thick (give thickness_m to choose; 0: solid)</source>
        <translation>le masque de %1 montre le sol sous le plateau en %2 points sur %3 : c&apos;est une plaque de %4 m d&apos;épaisseur (indiquez thickness_m pour choisir ; 0 : plein)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="77"/>
        <source>gathered light still changed by %1% in the last of %2 passes (the walls the camera does not see are uncertain)</source>
        <translation>la lumière réfléchie a encore changé de %1 % à la dernière des %2 passes (les murs que la caméra ne voit pas sont incertains)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="80"/>
        <source>lights %1 are out of view: they share one radiance (the photo shows only their sum)</source>
        <translation>les lumières %1 sont hors champ : elles partagent une même radiance (la photo ne montre que leur somme)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="83"/>
        <source>the ceiling the camera does not see: the light fit&apos;s model of the room gives it %1 grey, not the seen walls&apos; mean (%2; a sunlit patch lights the ceiling straight on, and the photo does not show its albedo)</source>
        <translation>le plafond que la caméra ne voit pas : le modèle de la pièce de l&apos;ajustement de la lumière lui donne un gris de %1, et non la moyenne des murs vus (%2 ; une tache de soleil éclaire le plafond de face, et la photo ne montre pas son albédo)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="87"/>
        <source>outside the room; moved %1 m to fit inside it</source>
        <translation>hors de la pièce ; déplacée de %1 m pour y tenir</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="88"/>
        <source>larger than the room in every direction; its position is kept</source>
        <translation>plus grande que la pièce dans toutes les directions ; sa position est gardée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="90"/>
        <source>%1 lights none of the room the photo shows: its intensity stays at its start</source>
        <translation>%1 n&apos;éclaire rien de la pièce que montre la photo : son intensité reste à sa valeur de départ</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="92"/>
        <source>the photo&apos;s direct light is black: the lights are fitted to darkness</source>
        <translation>la lumière directe de la photo est noire : les lumières sont ajustées sur l&apos;obscurité</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="94"/>
        <source>light refinement failed (%1): the start is kept</source>
        <translation>l&apos;affinage des lumières a échoué (%1) : le départ est gardé</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="97"/>
        <source>not converged: stopped by %1 after %2 iterations (%3 s): primal residual %4, dual %5, tolerance %6</source>
        <translation>non convergée : arrêtée par %1 après %2 itérations (%3 s) : résidu primal %4, dual %5, tolérance %6</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="100"/>
        <source>the iteration cap</source>
        <translation>la limite d&apos;itérations</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="101"/>
        <source>non-finite residuals</source>
        <translation>des résidus non finis</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="102"/>
        <source>cancellation</source>
        <translation>l&apos;annulation</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="106"/>
        <source>noise level</source>
        <translation>niveau de bruit</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="107"/>
        <source>edge</source>
        <translation>contours</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="108"/>
        <source>the fitted %1 lowers the %2 residual only from %3 to %4</source>
        <translation>la courbe ajustée %1 ne réduit le résidu (%2) que de %3 à %4</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="110"/>
        <source>the %1 residual of sRGB, %2, is within what photos read rightly as sRGB show (below %3), so the fitted %4 is not trusted</source>
        <translation>le résidu (%1) de sRGB, %2, reste dans ce que montrent les photos lues à juste titre en sRGB (moins de %3), donc la courbe ajustée %4 n&apos;est pas retenue</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="113"/>
        <source>the fitted %1 spans %2 stops between codes 128 and 254 (sRGB 2.2, at most %3 trusted), but the photo&apos;s noise was measured at only %4 code level in that half (%5 needed), so the shoulder is an extrapolation</source>
        <translation>la courbe ajustée %1 couvre %2 diaphragmes entre les codes 128 et 254 (sRGB 2,2, au plus %3 crédibles), mais le bruit de la photo n&apos;a été mesuré qu&apos;à %4 niveau de code dans cette moitié (%5 nécessaires), donc l&apos;épaule est une extrapolation</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="117"/>
        <source>the fitted %1 spans %2 stops between codes 128 and 254 (sRGB 2.2, at most %3 trusted), but the photo&apos;s noise was measured at only %4 code levels in that half (%5 needed), so the shoulder is an extrapolation</source>
        <translation>la courbe ajustée %1 couvre %2 diaphragmes entre les codes 128 et 254 (sRGB 2,2, au plus %3 crédibles), mais le bruit de la photo n&apos;a été mesuré qu&apos;à %4 niveaux de code dans cette moitié (%5 nécessaires), donc l&apos;épaule est une extrapolation</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="121"/>
        <source>too little evidence for a curve other than sRGB (%1)</source>
        <translation>trop peu d&apos;indices pour une autre courbe que sRGB (%1)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="123"/>
        <source>an implausible curve was refused (%1); using sRGB</source>
        <translation>une courbe invraisemblable a été refusée (%1) ; sRGB est utilisée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="125"/>
        <source>the light fit&apos;s residual with the fitted %1 is %2, with sRGB %3</source>
        <translation>le résidu de l&apos;ajustement de la lumière vaut %2 avec la courbe ajustée %1, %3 avec sRGB</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="127"/>
        <source>the estimated curve was not used (%1); using sRGB</source>
        <translation>la courbe estimée n&apos;a pas été utilisée (%1) ; sRGB est utilisée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="128"/>
        <source>the fitted %1 lies at the family&apos;s bound (%2): the camera&apos;s curve may be stronger than the family holds</source>
        <translation>la courbe ajustée %1 est à la limite de sa famille (%2) : la courbe de l&apos;appareil peut être plus forte que ce que la famille représente</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="131"/>
        <source>%1; using sRGB (give camera.response to choose)</source>
        <translation>%1 ; sRGB est utilisée (indiquez camera.response pour choisir)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="132"/>
        <source>the photo is empty</source>
        <translation>la photo est vide</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="133"/>
        <source>most of the photo is clipped to black or white</source>
        <translation>la plus grande partie de la photo est écrêtée en noir ou en blanc</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="134"/>
        <source>the photo is nearly one flat colour</source>
        <translation>la photo est presque d&apos;une seule couleur unie</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="135"/>
        <source>the photo is nearly binary (%1 grey levels in use)</source>
        <translation>la photo est presque binaire (%1 niveaux de gris utilisés)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="136"/>
        <source>too few clean edges between flat regions (%1 of %2 needed)</source>
        <translation>trop peu de contours nets entre des zones unies (%1 sur %2 nécessaires)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="138"/>
        <source>the edges cover only codes %1 to %2</source>
        <translation>les contours ne couvrent que les codes %1 à %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="139"/>
        <source>cancelled</source>
        <translation>annulée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="140"/>
        <source>too few flat regions to measure the noise (%1 flat 8 x 8 blocks)</source>
        <translation>trop peu de zones unies pour mesurer le bruit (%1 blocs unis de 8 x 8)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="142"/>
        <source>the flat regions cover too few codes to measure the noise against them</source>
        <translation>les zones unies couvrent trop peu de codes pour y mesurer le bruit</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="144"/>
        <source>the photo shows no measurable noise</source>
        <translation>la photo ne montre aucun bruit mesurable</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="155"/>
        <source>none marked</source>
        <translation>aucun marqué</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="156"/>
        <source>no sun marked</source>
        <translation>aucun soleil marqué</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="157"/>
        <source>none inserted</source>
        <translation>aucun inséré</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="158"/>
        <source>the lights are kept as estimated (initial lights asked for)</source>
        <translation>les lumières restent telles qu&apos;estimées (lumières initiales demandées)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="160"/>
        <source>turned off</source>
        <translation>désactivé</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="161"/>
        <source>no light marked</source>
        <translation>aucune lumière marquée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="162"/>
        <source>every light locked or given (&quot;refine&quot;: false)</source>
        <translation>chaque lumière verrouillée ou donnée (« refine » : false)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="163"/>
        <source>every light locked</source>
        <translation>chaque lumière verrouillée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="164"/>
        <source>the working copy is the photo</source>
        <translation>la copie de travail est la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="165"/>
        <source>the lights were not refined</source>
        <translation>les lumières n&apos;ont pas été affinées</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="166"/>
        <source>no light moved</source>
        <translation>aucune lumière déplacée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="167"/>
        <source>lights moved by at most %1 % of their size (under %2 %): the first estimate&apos;s lights are kept</source>
        <translation>lumières déplacées d&apos;au plus %1 % de leur taille (moins de %2 %) : les lumières de la première estimation sont conservées</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="170"/>
        <source>camera.vignetting is &quot;none&quot; (the default)</source>
        <translation>camera.vignetting vaut &quot;none&quot; (par défaut)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="172"/>
        <source>%1 x %2 px</source>
        <translation>%1 x %2 px</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="173"/>
        <source>linear photo</source>
        <translation>photo linéaire</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="174"/>
        <source>estimated</source>
        <translation>estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="175"/>
        <source>the photo area-averaged</source>
        <translation>la photo réduite par moyenne de surface</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="176"/>
        <source>the photo&apos;s own size</source>
        <translation>la taille propre de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="177"/>
        <source>estimated from the photo</source>
        <translation>estimée d&apos;après la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="178"/>
        <source>the file&apos;s vanishing points and back wall</source>
        <translation>points de fuite et mur du fond du fichier</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="179"/>
        <source>estimated from the photo once, for the response check&apos;s copy</source>
        <translation>estimée une seule fois d&apos;après la photo, pour la copie de la vérification de la courbe de réponse</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="181"/>
        <source>%1 x %2 m</source>
        <translation>%1 x %2 m</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="182"/>
        <source>%1 m high</source>
        <translation>%1 m de haut</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="183"/>
        <source>%1 matte</source>
        <translation>%1 masque</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="184"/>
        <source>%1 mattes</source>
        <translation>%1 masques</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="185"/>
        <source>v %1 applied</source>
        <translation>v %1 appliqué</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="186"/>
        <source>the light fit&apos;s residual shows %1</source>
        <translation>le résidu de l&apos;ajustement des lumières montre %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="187"/>
        <source>the light fit run again</source>
        <translation>l&apos;ajustement des lumières refait</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="188"/>
        <source>%1 surface built</source>
        <translation>%1 surface construite</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="189"/>
        <source>%1 surfaces built</source>
        <translation>%1 surfaces construites</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="190"/>
        <source>%1 surface</source>
        <translation>%1 surface</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="191"/>
        <source>%1 surfaces</source>
        <translation>%1 surfaces</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="192"/>
        <source>%1 reflective</source>
        <translation>%1 réfléchissante(s)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="193"/>
        <source>%1 outlined</source>
        <translation>%1 détourée(s)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="194"/>
        <source>%1 placed in 3D</source>
        <translation>%1 placée(s) en 3D</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="195"/>
        <source>%1 sun</source>
        <translation>%1 soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="196"/>
        <source>%1 suns</source>
        <translation>%1 soleils</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="197"/>
        <source>%1 sky through an unseen window</source>
        <translation>%1 ciel par une fenêtre hors champ</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="198"/>
        <source>%1 skies through unseen windows</source>
        <translation>%1 ciels par des fenêtres hors champ</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="199"/>
        <source>%1 light</source>
        <translation>%1 lumière</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="200"/>
        <source>%1 lights</source>
        <translation>%1 lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="201"/>
        <source>%1 pass</source>
        <translation>%1 passe</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="202"/>
        <source>%1 passes</source>
        <translation>%1 passes</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="203"/>
        <source>the first estimate&apos;s rays replayed</source>
        <translation>rayons de la première estimation rejoués</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="204"/>
        <source>%1 points x %2 rays</source>
        <translation>%1 points x %2 rayons</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="205"/>
        <source>%1 light fit iterations</source>
        <translation>%1 itérations de l&apos;ajustement des lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="206"/>
        <source>%1 of %2 light refined</source>
        <translation>%1 lumière sur %2 affinée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="207"/>
        <source>%1 of %2 lights refined</source>
        <translation>%1 lumières sur %2 affinées</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="208"/>
        <source>%1 evaluation</source>
        <translation>%1 évaluation</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="209"/>
        <source>%1 evaluations</source>
        <translation>%1 évaluations</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="210"/>
        <source>lights moved by at most %1 % of their size; the first estimate fits the photo better (log residual %2 against %3) and is kept; the refit took %4</source>
        <translation>lumières déplacées d&apos;au plus %1 % de leur taille ; la première estimation s&apos;accorde mieux à la photo (résidu log %2 contre %3) et est conservée ; le réajustement a pris %4</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="213"/>
        <source>lights moved by at most %1 % of their size; the refit is kept (log residual %2 against the first estimate&apos;s %3)</source>
        <translation>lumières déplacées d&apos;au plus %1 % de leur taille ; le réajustement est conservé (résidu log %2 contre %3 pour la première estimation)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="216"/>
        <source>from %1 x %2 px: maps %3 s</source>
        <translation>depuis %1 x %2 px : cartes %3 s</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="217"/>
        <source>surfaces cast %1 s</source>
        <translation>surfaces par pixel %1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="218"/>
        <source>%1 object</source>
        <translation>%1 objet</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="219"/>
        <source>%1 objects</source>
        <translation>%1 objets</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="220"/>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="223"/>
        <source>the curve kept: %1</source>
        <translation>courbe conservée : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="224"/>
        <source>sRGB kept: %1</source>
        <translation>sRGB conservé : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="225"/>
        <source>the light fit&apos;s residual with the fitted %1 is %2</source>
        <translation>le résidu de l&apos;ajustement de la lumière vaut %2 avec la courbe ajustée %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="23"/>
        <source>toe_shoulder (power %1, toe %2, shoulder %3)</source>
        <translation>toe_shoulder (exposant %1, pied %2, épaule %3)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="27"/>
        <source>vanishing point %1: only %2 supporting line(s); it rests on the other two</source>
        <translation>point de fuite %1 : seulement %2 ligne(s) d’appui ; il repose sur les deux autres</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="29"/>
        <source>vanishing point %1: its lines are nearly parallel in the photo, so its distance is uncertain</source>
        <translation>point de fuite %1 : ses lignes sont presque parallèles sur la photo, sa distance est donc incertaine</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="227"/>
        <source>with sRGB %1; on %2 x %3 copies %4 against %5</source>
        <translation>%1 avec sRGB ; sur des copies de %2 x %3 px %4 contre %5</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="228"/>
        <source>with sRGB %1; no quick comparison</source>
        <translation>%1 avec sRGB ; pas de comparaison rapide</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="229"/>
        <source>log ratio %1 beyond %2</source>
        <translation>rapport log %1 au-delà de %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="230"/>
        <source>log ratio %1 within %2</source>
        <translation>rapport log %1 en deçà de %2</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="235"/>
        <source>line %1</source>
        <translation>ligne %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="236"/>
        <source>header line %1</source>
        <translation>ligne d&apos;en-tête %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="237"/>
        <source>vertex %1</source>
        <translation>sommet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="238"/>
        <source>face %1</source>
        <translation>face %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="239"/>
        <source>sun %1</source>
        <translation>soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="240"/>
        <source>lights</source>
        <translation>lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="241"/>
        <source>estimate</source>
        <translation>estimation</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="242"/>
        <source>lighting</source>
        <translation>éclairage</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="243"/>
        <source>lighting (refit)</source>
        <translation>éclairage (réajusté)</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="244"/>
        <source>light refinement</source>
        <translation>affinage des lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="245"/>
        <source>decomposition</source>
        <translation>décomposition</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="246"/>
        <source>layout</source>
        <translation>disposition</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="247"/>
        <source>camera response</source>
        <translation>réponse de l&apos;appareil</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="248"/>
        <source>kept sRGB</source>
        <translation>sRGB conservée</translation>
    </message>
    <message>
        <location filename="../app/studio/engine_text.cpp" line="311"/>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
</context>
<context>
    <name>inlay::studio::FinalRender</name>
    <message>
        <location filename="../app/studio/final_render.cpp" line="81"/>
        <source>Render Final Image cancelled; nothing was written.</source>
        <translation>Image finale annulée ; rien n&apos;a été écrit.</translation>
    </message>
    <message>
        <location filename="../app/studio/final_render.cpp" line="129"/>
        <source>Wrote %1: %2 × %3, %4 samples per pixel at most (%5 on average), estimated error %6 before denoising, %7 s</source>
        <translation>%1 écrit : %2 × %3, %4 échantillons par pixel au plus (%5 en moyenne), erreur estimée %6 avant débruitage, %7 s</translation>
    </message>
    <message>
        <location filename="../app/studio/final_render.cpp" line="131"/>
        <source>Wrote %1: %2 × %3, %4 samples per pixel at most (%5 on average), estimated error %6, %7 s</source>
        <translation>%1 écrit : %2 × %3, %4 échantillons par pixel au plus (%5 en moyenne), erreur estimée %6, %7 s</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LayersDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="254"/>
        <source>Layers</source>
        <translation>Calques</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="255"/>
        <source>Composite</source>
        <translation>Composition</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="255"/>
        <source>Photo</source>
        <translation>Photo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="255"/>
        <source>Albedo</source>
        <translation>Albédo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="256"/>
        <source>Direct light</source>
        <translation>Lumière directe</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="256"/>
        <source>With objects</source>
        <translation>Avec les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="256"/>
        <source>Without objects</source>
        <translation>Sans les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="257"/>
        <source>Mask</source>
        <translation>Masque</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="257"/>
        <source>Difference</source>
        <translation>Différence</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LibraryDock</name>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="23"/>
        <source>Chair</source>
        <translation>Chaise</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="24"/>
        <source>Armchair</source>
        <translation>Fauteuil</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="25"/>
        <source>Sofa</source>
        <translation>Canapé</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="26"/>
        <source>Coffee table</source>
        <translation>Table basse</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="27"/>
        <source>Dining table</source>
        <translation>Table de salle à manger</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="28"/>
        <source>Stool</source>
        <translation>Tabouret</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="29"/>
        <source>Floor lamp</source>
        <translation>Lampadaire</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="30"/>
        <source>Table lamp</source>
        <translation>Lampe de table</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="31"/>
        <source>Vase</source>
        <translation>Vase</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="32"/>
        <source>Potted plant</source>
        <translation>Plante en pot</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="33"/>
        <source>Bookshelf</source>
        <translation>Étagère à livres</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="34"/>
        <source>Rug</source>
        <translation>Tapis</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="106"/>
        <source>Library</source>
        <translation>Bibliothèque de modèles</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="109"/>
        <source>no library.json in $INLAY_MODELS_DIR, &lt;prefix&gt;/share/inlay/models or resources/models</source>
        <translation>aucun library.json dans $INLAY_MODELS_DIR, &lt;prefix&gt;/share/inlay/models ni resources/models</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="112"/>
        <source>The model library could not be shown: %1</source>
        <translation>La bibliothèque de modèles ne peut pas être affichée : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/library_dock.cpp" line="118"/>
        <source>%1
%2 × %3 × %4 m (width × depth × height)
Drag it into the photo.</source>
        <translation>%1
%2 × %3 × %4 m (largeur × profondeur × hauteur)
Faites-le glisser dans la photo.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LogDock</name>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="31"/>
        <source>Log</source>
        <translation>Journal</translation>
    </message>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="39"/>
        <source>%1 The scene could not be prepared: %2</source>
        <translation>%1 La scène n&apos;a pas pu être préparée : %2</translation>
    </message>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="46"/>
        <source>%1 Prepared the scene in %2 s:</source>
        <translation>%1 Scène préparée en %2 s :</translation>
    </message>
    <message>
        <location filename="../app/studio/log_dock.cpp" line="49"/>
        <source>warning: %1</source>
        <translation>avertissement : %1</translation>
    </message>
</context>
<context>
    <name>inlay::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="90"/>
        <source>Reading the photo</source>
        <translation>Lecture de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="91"/>
        <source>Estimating the camera</source>
        <translation>Estimation de l&apos;appareil photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="92"/>
        <source>Fitting the room</source>
        <translation>Ajustement de la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="93"/>
        <source>Estimating the lighting</source>
        <translation>Estimation de l&apos;éclairage</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="95"/>
        <source>Placing the objects</source>
        <translation>Placement des objets</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="500"/>
        <source>Samples per pixel of the shown composite</source>
        <translation>Échantillons par pixel de la composition affichée</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="501"/>
        <source>Samples per second of the renderer (millions)</source>
        <translation>Échantillons par seconde du rendu (millions)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="502"/>
        <source>Estimated error (RMSE in sRGB) where the objects change the photo</source>
        <translation>Erreur estimée (RMSE en sRGB) là où les objets modifient la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="503"/>
        <source>Render time since the last change</source>
        <translation>Temps de rendu depuis la dernière modification</translation>
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
        <translation>Préparation de la scène : %1…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="445"/>
        <source>&amp;Open Scene…</source>
        <translation>&amp;Ouvrir une scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="486"/>
        <source>Open a scene file (.json)</source>
        <translation>Ouvrir un fichier de scène (.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="446"/>
        <source>Open &amp;Photo…</source>
        <translation>Ouvrir une &amp;photo…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="487"/>
        <source>Start a new scene from a photo</source>
        <translation>Commencer une nouvelle scène à partir d&apos;une photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="447"/>
        <source>Open &amp;Example</source>
        <translation>Ouvrir l&apos;&amp;exemple</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="448"/>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="449"/>
        <source>Save &amp;As…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="450"/>
        <source>&amp;Export Composite…</source>
        <translation>E&amp;xporter la composition…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="488"/>
        <source>Write the current composite as PNG, JPEG, TIFF or EXR</source>
        <translation>Écrire la composition actuelle en PNG, JPEG, TIFF ou EXR</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="451"/>
        <source>Export Shown &amp;Layer…</source>
        <translation>Exporter le &amp;calque affiché…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="490"/>
        <source>Write the layer the viewport shows (albedo, mask, …) as an 8-bit image</source>
        <translation>Écrire le calque affiché (albédo, masque, …) en image 8 bits</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="452"/>
        <source>Export Scene as &amp;glTF…</source>
        <translation>Exporter la scène en &amp;glTF…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="492"/>
        <source>Write the room, its lights, the camera and the objects as glTF 2.0, to go on in Blender</source>
        <translation>Écrire la pièce, ses lumières, la caméra et les objets en glTF 2.0, pour continuer dans Blender</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="460"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="542"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="543"/>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="461"/>
        <source>Insert &amp;Sphere</source>
        <translation>Insérer une &amp;sphère</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="493"/>
        <source>Stand a sphere on the floor in the middle of the photo</source>
        <translation>Poser une sphère sur le sol au milieu de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="462"/>
        <source>Insert &amp;Cube</source>
        <translation>Insérer un &amp;cube</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="494"/>
        <source>Stand a cube on the floor in the middle of the photo</source>
        <translation>Poser un cube sur le sol au milieu de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="463"/>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="495"/>
        <source>Delete the selected object or mark</source>
        <translation>Supprimer l&apos;objet ou le repère sélectionné</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="474"/>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;avant</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="475"/>
        <source>Zoom &amp;Out</source>
        <translation>Zoom a&amp;rrière</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="476"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Ajuster à la fenêtre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="477"/>
        <source>&amp;Before (Photo Only)</source>
        <translation>&amp;Avant (photo seule)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="496"/>
        <source>Toggle between the photo and the composite with the objects</source>
        <translation>Basculer entre la photo et la composition avec les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="478"/>
        <source>&amp;Accept Estimated Box</source>
        <translation>Accepter la &amp;pièce estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="497"/>
        <source>Keep the estimated back wall as yours</source>
        <translation>Garder le mur du fond estimé comme le vôtre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="479"/>
        <source>Estimate the &amp;Box Again</source>
        <translation>Estimer à nouveau la &amp;pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="498"/>
        <source>Forget your corners of the back wall</source>
        <translation>Oublier vos coins du mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="480"/>
        <source>&amp;Prepare the Scene Again</source>
        <translation>P&amp;réparer à nouveau la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="499"/>
        <source>Estimate the camera, room and lighting again (after a cancel)</source>
        <translation>Estimer à nouveau l&apos;appareil photo, la pièce et l&apos;éclairage (après une annulation)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="481"/>
        <source>&amp;Vanishing Lines and Confidence</source>
        <translation>Lignes de &amp;fuite et confiance</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="505"/>
        <source>&amp;Select and Move</source>
        <translation>&amp;Sélectionner et déplacer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="505"/>
        <source>Outline a &amp;Light</source>
        <translation>Détourer une &amp;lampe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="506"/>
        <source>Sun &amp;Shaft</source>
        <translation>Rayon de &amp;soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="506"/>
        <source>&amp;Table Top or Step</source>
        <translation>Dessus de &amp;table ou marche</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="507"/>
        <source>&amp;Occluder Strokes</source>
        <translation>Traits de masque d&apos;&amp;avant-plan</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="485"/>
        <source>&amp;About Inlay</source>
        <translation>À &amp;propos d’Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="94"/>
        <source>Refining the lights</source>
        <translation>Affinage des lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="453"/>
        <source>&amp;Render Final Image…</source>
        <translation>&amp;Rendre l&apos;image finale…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="455"/>
        <source>Render the composite at the photo&apos;s full resolution until it is clean, then save it (PNG, JPEG, TIFF or EXR)</source>
        <translation>Rendre le composite à la pleine résolution de la photo jusqu&apos;à ce qu&apos;il soit net, puis l&apos;enregistrer (PNG, JPEG, TIFF ou EXR)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="457"/>
        <source>Before/After &amp;Split</source>
        <translation>&amp;Partage avant/après</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="459"/>
        <source>The photo left of a divider, the composite right of it; drag the divider</source>
        <translation>La photo à gauche d&apos;une séparation, le composite à droite ; faites glisser la séparation</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="464"/>
        <source>Insert &amp;Model…</source>
        <translation>Insérer un &amp;modèle…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="466"/>
        <source>Stand a 3D model (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) on the floor; or drop the file where it should stand</source>
        <translation>Poser un modèle 3D (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) au sol ; ou déposer le fichier là où il doit se tenir</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="468"/>
        <source>D&amp;uplicate</source>
        <translation>D&amp;upliquer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="469"/>
        <source>Stand a copy of the selected object beside it</source>
        <translation>Poser une copie de l&apos;objet choisi à côté de lui</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="470"/>
        <source>Re&amp;name…</source>
        <translation>Re&amp;nommer…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="471"/>
        <source>Rename the selected object (in the Scene list)</source>
        <translation>Renommer l&apos;objet choisi (dans la liste de la scène)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="472"/>
        <source>&amp;Hide or Show</source>
        <translation>&amp;Masquer ou afficher</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="473"/>
        <source>Hide the selected object from the render, or show it again</source>
        <translation>Masquer l&apos;objet choisi du rendu, ou l&apos;afficher à nouveau</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="482"/>
        <source>&amp;Denoise Preview</source>
        <translation>&amp;Débruiter l&apos;aperçu</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="484"/>
        <source>Smooth the render&apos;s noise where the objects change the photo (the rest stays the photo)</source>
        <translation>Lisser le bruit du rendu là où les objets changent la photo (le reste reste la photo)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="507"/>
        <source>&amp;Vanishing Lines (X, Y, Z)</source>
        <translation>&amp;Lignes de fuite (X, Y, Z)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="509"/>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="510"/>
        <source>Open &amp;Recent</source>
        <translation>Ouvrir un fichier &amp;récent</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="511"/>
        <source>&amp;Edit</source>
        <translation>&amp;Édition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="512"/>
        <source>&amp;Tools</source>
        <translation>&amp;Outils</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="513"/>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="514"/>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="515"/>
        <source>System Default</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="516"/>
        <source>&amp;Help</source>
        <translation>A&amp;ide</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="517"/>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="542"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annuler : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="543"/>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rétablir : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="552"/>
        <location filename="../app/studio/main_window.cpp" line="567"/>
        <location filename="../app/studio/main_window.cpp" line="644"/>
        <source>Preparing the scene…</source>
        <translation>Préparation de la scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="552"/>
        <location filename="../app/studio/main_window.cpp" line="933"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
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
        <translation>La scène n&apos;a pas pu être préparée</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/main_window.cpp" line="596"/>
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (et %n autre)</numerusform>
            <numerusform>%1 (et %n autres)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="625"/>
        <source>%1: the scene could not be prepared, so the model has nowhere to stand.</source>
        <translation>%1 : la scène n&apos;a pas pu être préparée, le modèle n&apos;a donc nulle part où se tenir.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="530"/>
        <location filename="../app/studio/main_window.cpp" line="665"/>
        <source>– spp</source>
        <translation>– éch./px</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="532"/>
        <location filename="../app/studio/main_window.cpp" line="658"/>
        <location filename="../app/studio/main_window.cpp" line="666"/>
        <location filename="../app/studio/main_window.cpp" line="680"/>
        <source>– samples/s</source>
        <translation>– éch./s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="533"/>
        <location filename="../app/studio/main_window.cpp" line="667"/>
        <source>error –</source>
        <translation>erreur –</translation>
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
        <translation>final, %1 éch./px</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="529"/>
        <location filename="../app/studio/main_window.cpp" line="672"/>
        <source>preview 1/%1</source>
        <translation>aperçu 1/%1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="529"/>
        <location filename="../app/studio/main_window.cpp" line="673"/>
        <source>%1 spp, done</source>
        <translation>%1 éch./px, terminé</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="674"/>
        <source>%1 spp</source>
        <translation>%1 éch./px</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1394"/>
        <source>The final image %1 is still being rendered (%2 % done). Cancel the render? Nothing is written then, and an earlier file of that name stays as it was.</source>
        <translation>L&apos;image finale %1 est encore en cours de rendu (%2 % fait). Annuler le rendu ? Rien n&apos;est alors écrit, et un fichier antérieur de ce nom reste tel quel.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1402"/>
        <source>Keep Rendering</source>
        <translation>Continuer le rendu</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1421"/>
        <source>Cancel the Render and Close</source>
        <translation>Annuler le rendu et fermer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="533"/>
        <location filename="../app/studio/main_window.cpp" line="659"/>
        <location filename="../app/studio/main_window.cpp" line="675"/>
        <source>error %1</source>
        <translation>erreur %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="532"/>
        <location filename="../app/studio/main_window.cpp" line="679"/>
        <source>%1 M samples/s</source>
        <translation>%1 M éch./s</translation>
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
        <translation>%1 (nouvelle scène)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="692"/>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="693"/>
        <source>%1[*] — Inlay</source>
        <translation>%1[*] — Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="714"/>
        <source>Cancel the Render and Open</source>
        <translation>Annuler le rendu et ouvrir</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="718"/>
        <source>Cannot open</source>
        <translation>Ouverture impossible</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="718"/>
        <source>%1: no such file</source>
        <translation>%1 : fichier introuvable</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="724"/>
        <source>Cannot open the scene</source>
        <translation>Impossible d&apos;ouvrir la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="743"/>
        <location filename="../app/studio/main_window.cpp" line="753"/>
        <source>Cannot open the example</source>
        <translation>Impossible d&apos;ouvrir l&apos;exemple</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="743"/>
        <source>The example scene is not installed.</source>
        <translation>La scène d&apos;exemple n&apos;est pas installée.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="753"/>
        <source>Cannot write %1</source>
        <translation>Impossible d&apos;écrire %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="763"/>
        <source>Open Scene</source>
        <translation>Ouvrir une scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="764"/>
        <source>Inlay scenes (*.json);;All files (*)</source>
        <translation>Scènes Inlay (*.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="771"/>
        <source>Open Photo</source>
        <translation>Ouvrir une photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="772"/>
        <source>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)</source>
        <translation>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="779"/>
        <source>Cannot save the scene</source>
        <translation>Impossible d&apos;enregistrer la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="783"/>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="799"/>
        <source>Save Scene As</source>
        <translation>Enregistrer la scène sous</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="799"/>
        <source>Inlay scenes (*.json)</source>
        <translation>Scènes Inlay (*.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="807"/>
        <location filename="../app/studio/main_window.cpp" line="838"/>
        <location filename="../app/studio/main_window.cpp" line="1034"/>
        <location filename="../app/studio/main_window.cpp" line="1065"/>
        <source>Nothing to export</source>
        <translation>Rien à exporter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="807"/>
        <location filename="../app/studio/main_window.cpp" line="838"/>
        <source>The composite has not been rendered yet.</source>
        <translation>La composition n&apos;a pas encore été rendue.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="830"/>
        <location filename="../app/studio/main_window.cpp" line="1054"/>
        <source>PNG image (*.png)</source>
        <translation>Image PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="830"/>
        <location filename="../app/studio/main_window.cpp" line="1054"/>
        <source>JPEG image (*.jpg *.jpeg)</source>
        <translation>Image JPEG (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="830"/>
        <location filename="../app/studio/main_window.cpp" line="1055"/>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>Image TIFF (*.tif *.tiff)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="831"/>
        <source>OpenEXR, linear (*.exr)</source>
        <translation>OpenEXR, linéaire (*.exr)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="810"/>
        <source>Export Composite</source>
        <translation>Exporter la composition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="846"/>
        <source>Cannot export the composite</source>
        <translation>Impossible d&apos;exporter la composition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="851"/>
        <source>Exported %1 (the final render)</source>
        <translation>%1 exporté (l&apos;image finale)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="856"/>
        <source>Exported %1 (%2 spp, the preview&apos;s %3 × %4; Render Final Image writes the photo&apos;s full size)</source>
        <translation>%1 exporté (%2 spp, l&apos;aperçu en %3 × %4 ; Rendre l&apos;image finale écrit la pleine taille de la photo)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="864"/>
        <source>Exported %1 (%2 spp)</source>
        <translation>%1 exporté (%2 éch./px)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="887"/>
        <source>All four steps done. View &gt; Steps shows them again.</source>
        <translation>Les quatre étapes sont faites. Affichage &gt; Étapes les montre à nouveau.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="893"/>
        <location filename="../app/studio/main_window.cpp" line="908"/>
        <source>Nothing to render</source>
        <translation>Rien à rendre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="901"/>
        <location filename="../app/studio/main_window.cpp" line="934"/>
        <location filename="../app/studio/main_window.cpp" line="1393"/>
        <source>Render Final Image</source>
        <translation>Rendre l&apos;image finale</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="912"/>
        <source>A final image is being rendered already.</source>
        <translation>Une image finale est déjà en cours de rendu.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="919"/>
        <location filename="../app/studio/main_window.cpp" line="924"/>
        <source>Cannot render the final image</source>
        <translation>Impossible de rendre l&apos;image finale</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="920"/>
        <source>%1: choose a .png, .jpg, .tif or .exr file.</source>
        <translation>%1 : choisissez un fichier .png, .jpg, .tif ou .exr.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="925"/>
        <source>%1: the folder %2 does not exist.</source>
        <translation>%1 : le dossier %2 n&apos;existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="933"/>
        <location filename="../app/studio/main_window.cpp" line="954"/>
        <source>Rendering the final image…</source>
        <translation>Rendu de l&apos;image finale…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="942"/>
        <source>Rendering the final image: %1 samples per pixel at most, estimated error %2 (target %3), %4 s</source>
        <translation>Image finale : %1 échantillons par pixel au plus, erreur estimée %2 (cible %3), %4 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="978"/>
        <source>Cannot write the final image</source>
        <translation>Impossible d&apos;écrire l&apos;image finale</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="999"/>
        <source>Final render shown (%1, %2 × %3); the next edit returns to the live preview.</source>
        <translation>Image finale affichée (%1, %2 × %3) ; la prochaine modification revient à l&apos;aperçu en direct.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1003"/>
        <source>Final render (%1 × %2, saved as %3): shown until the next edit</source>
        <translation>Image finale (%1 × %2, enregistrée sous %3) : affichée jusqu&apos;à la prochaine modification</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1022"/>
        <source>glTF 2.0, separate files (*.gltf)</source>
        <translation>glTF 2.0, fichiers séparés (*.gltf)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1022"/>
        <source>glTF 2.0, binary (*.glb)</source>
        <translation>glTF 2.0, binaire (*.glb)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1023"/>
        <source>Export Scene as glTF</source>
        <translation>Exporter la scène en glTF</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="893"/>
        <location filename="../app/studio/main_window.cpp" line="908"/>
        <location filename="../app/studio/main_window.cpp" line="1034"/>
        <source>The scene is not prepared yet.</source>
        <translation>La scène n’est pas encore préparée.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1041"/>
        <source>Cannot export the scene</source>
        <translation>Impossible d’exporter la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1053"/>
        <source>Export Shown Layer</source>
        <translation>Exporter le calque affiché</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1065"/>
        <source>This layer has not been made yet.</source>
        <translation>Ce calque n&apos;a pas encore été calculé.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1072"/>
        <source>Cannot export the layer</source>
        <translation>Impossible d&apos;exporter le calque</translation>
    </message>
    <message>
        <source>%1: cannot write (%2)</source>
        <translation type="vanished">%1 : écriture impossible (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1044"/>
        <location filename="../app/studio/main_window.cpp" line="1075"/>
        <source>Exported %1</source>
        <translation>%1 exporté</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1105"/>
        <source>About Inlay</source>
        <translation>À propos d’Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1106"/>
        <source>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Inserts synthetic objects into an ordinary photograph: a box room is fitted to the photo, its lights and reflectance are estimated, and a path tracer renders the objects into it (after Karsch et al., 2011).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Insère des objets de synthèse dans une photographie ordinaire : une pièce en forme de boîte est ajustée à la photo, ses lampes et sa réflectance sont estimées, et un lancer de chemins y rend les objets (d’après Karsch et al., 2011).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1115"/>
        <source>There is no floor in the middle of the photo to stand an object on.</source>
        <translation>Il n&apos;y a pas de sol au milieu de la photo où poser un objet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1142"/>
        <source>Insert Model</source>
        <translation>Insérer un modèle</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1150"/>
        <source>%1: open a photo first; the model needs a room to stand in.</source>
        <translation>%1 : ouvrez d&apos;abord une photo ; le modèle a besoin d&apos;une pièce où se tenir.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1154"/>
        <source>%1: not a model file Inlay reads (%2).</source>
        <translation>%1 : pas un fichier de modèle que lit Inlay (%2).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1169"/>
        <source>Reading %1…</source>
        <translation>Lecture de %1…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1179"/>
        <source>%1 goes in once the scene is prepared.</source>
        <translation>%1 sera inséré dès que la scène sera prête.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1220"/>
        <source>%1: there is no floor, table top or step under the drop point to stand it on.</source>
        <translation>%1 : il n&apos;y a ni sol, ni plateau, ni marche sous le point de dépôt pour le poser.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1222"/>
        <source>%1: there is no floor in the middle of the photo to stand it on.</source>
        <translation>%1 : il n&apos;y a pas de sol au milieu de la photo pour le poser.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1192"/>
        <source>%1 is %2 m high at its own size, taller than the room (%3 m): it was inserted %4 m high instead (change Height in Properties).</source>
        <translation>%1 mesure %2 m de haut à sa propre taille, plus que la pièce (%3 m) : il a été inséré à %4 m de haut (modifiez la hauteur dans les Propriétés).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1205"/>
        <source>%1 is %2 m wide at its own size, wider than the room (%3 m): it was inserted %4 m high instead (change Height in Properties).</source>
        <translation>%1 mesure %2 m de large à sa propre taille, plus que la pièce (%3 m) : il a été inséré à %4 m de haut (modifiez la hauteur dans les Propriétés).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1248"/>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1252"/>
        <source>Inserted %1, %2 m high (its own size).</source>
        <translation>%1 inséré, %2 m de haut (sa propre taille).</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1253"/>
        <source>Inserted %1, %2 m high.</source>
        <translation>%1 inséré, %2 m de haut.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1262"/>
        <source>Cannot insert the model</source>
        <translation>Impossible d&apos;insérer le modèle</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1282"/>
        <source>Select an object to rename.</source>
        <translation>Choisissez un objet à renommer.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1312"/>
        <source>Models</source>
        <translation>Modèles</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1314"/>
        <source>Insert %1</source>
        <translation>Insérer %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1339"/>
        <source>a new scene</source>
        <translation>une nouvelle scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1342"/>
        <source>Restore unsaved work?</source>
        <translation>Restaurer le travail non enregistré ?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1343"/>
        <source>Inlay did not close properly. Unsaved work on %1 was kept at %2. Restore it?</source>
        <translation>Inlay ne s&apos;est pas fermé correctement. Le travail non enregistré sur %1 a été conservé à %2. Le restaurer ?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1347"/>
        <source>&amp;Restore</source>
        <translation>&amp;Restaurer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1348"/>
        <source>&amp;Discard</source>
        <translation>&amp;Abandonner</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1365"/>
        <source>Cannot restore the unsaved work</source>
        <translation>Impossible de restaurer le travail non enregistré</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1371"/>
        <source>Restored the unsaved work.</source>
        <translation>Le travail non enregistré a été restauré.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="1378"/>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>La scène a des modifications non enregistrées. Les enregistrer ?</translation>
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
        <translation>Les fichiers %1 n&apos;indiquent pas leur unité : %2 a été mis à l&apos;échelle à %3 de haut (modifiez la hauteur dans les Propriétés).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="50"/>
        <source>%1 says it is %2 high, an absurd size: it was inserted %3 high instead (change Height in Properties).</source>
        <translation>%1 se dit haut de %2, une taille absurde : il a été inséré à %3 de haut (modifiez la hauteur dans les Propriétés).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="109"/>
        <source>%1 names files that are not beside it (%2): its materials&apos; own colours are used, or a grey default.</source>
        <translation>%1 cite des fichiers absents à côté de lui (%2) : les couleurs propres de ses matériaux sont utilisées, sinon un gris.</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="114"/>
        <source>%1&apos;s image textures are not rendered: Inlay uses its materials&apos; base colour, metallic and roughness values.</source>
        <translation>Les textures d&apos;image de %1 ne sont pas rendues : Inlay utilise la couleur de base, le métal et la rugosité de ses matériaux.</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="137"/>
        <source>3D models (%1)</source>
        <translation>Modèles 3D (%1)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="138"/>
        <source>All files (*)</source>
        <translation>Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="152"/>
        <source>%1: not a model file Inlay reads (%2).</source>
        <translation>%1 : pas un fichier de modèle que lit Inlay (%2).</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="170"/>
        <source>%1: %2</source>
        <translation>%1 : %2</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="174"/>
        <source>(Inlay inserts models of up to %1 triangles.)</source>
        <translation>(Inlay insère des modèles jusqu&apos;à %1 triangles.)</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="179"/>
        <source>%1: the model is flat (it has no height), so it cannot stand in the room.</source>
        <translation>%1 : le modèle est plat (il n&apos;a pas de hauteur) et ne peut donc pas se tenir dans la pièce.</translation>
    </message>
    <message>
        <location filename="../app/studio/model_import.cpp" line="190"/>
        <source>%1 has no normals: it is shaded flat.</source>
        <translation>%1 n&apos;a pas de normales : il est ombré à plat.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PrepareWorker</name>
    <message>
        <location filename="../app/studio/prepare_worker.cpp" line="98"/>
        <source>Internal error while preparing the scene.</source>
        <translation>Erreur interne pendant la préparation de la scène.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PropertiesDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="386"/>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="391"/>
        <source>Name:</source>
        <translation>Nom :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="392"/>
        <source>Render:</source>
        <translation>Rendu :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="393"/>
        <source>Shown</source>
        <translation>Affiché</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="394"/>
        <source>A hidden object stays in the scene but is not rendered</source>
        <translation>Un objet masqué reste dans la scène mais n&apos;est pas rendu</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="395"/>
        <source>Size (W × D × H):</source>
        <translation>Taille (L × P × H) :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="396"/>
        <source>Width × depth × height in metres, as placed (before its turn)</source>
        <translation>Largeur × profondeur × hauteur en mètres, telle que placée (avant sa rotation)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="398"/>
        <source>The photo pixel the centre of the object&apos;s base stands on</source>
        <translation>Le pixel de la photo sur lequel repose le centre de la base de l&apos;objet</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="403"/>
        <source>Surface:</source>
        <translation>Surface :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="404"/>
        <source>Finish:</source>
        <translation>Finition :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="405"/>
        <source>Roughness:</source>
        <translation>Rugosité :</translation>
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
        <translation>Diffus</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="408"/>
        <location filename="../app/studio/docks.cpp" line="413"/>
        <source>Glossy</source>
        <translation>Brillant</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="408"/>
        <location filename="../app/studio/docks.cpp" line="413"/>
        <source>Mirror</source>
        <translation>Miroir</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="408"/>
        <source>Metal</source>
        <translation>Métal</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>Glass</source>
        <translation>Verre</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>Frosted glass</source>
        <translation>Verre dépoli</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>Emissive</source>
        <translation>Émissif</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="409"/>
        <source>From the file</source>
        <translation>Celui du fichier</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="411"/>
        <source>Reflectance of the object&apos;s surface</source>
        <translation>Réflectance de la surface de l&apos;objet</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="397"/>
        <source>Base (px):</source>
        <translation>Base (px) :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="83"/>
        <source>Floor</source>
        <translation>Sol</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="84"/>
        <source>Ceiling</source>
        <translation>Plafond</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="85"/>
        <source>Left wall</source>
        <translation>Mur de gauche</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="86"/>
        <source>Right wall</source>
        <translation>Mur de droite</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="87"/>
        <source>Back wall</source>
        <translation>Mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="88"/>
        <source>Wall behind the camera</source>
        <translation>Mur derrière l&apos;appareil</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="92"/>
        <source>Surface %1, top</source>
        <translation>Surface %1, dessus</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="93"/>
        <source>Surface %1, sides</source>
        <translation>Surface %1, côtés</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="399"/>
        <location filename="../app/studio/docks.cpp" line="417"/>
        <source>Height:</source>
        <translation>Hauteur :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="400"/>
        <source>Turn:</source>
        <translation>Rotation :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="401"/>
        <source>Material:</source>
        <translation>Matériau :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="402"/>
        <source>Colour:</source>
        <translation>Couleur :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="412"/>
        <source>&lt;b&gt;Room surface&lt;/b&gt;</source>
        <translation>&lt;b&gt;Surface de la pièce&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="413"/>
        <source>Matte</source>
        <translation>Mat</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="415"/>
        <source>A real surface of the photo that reflects: a glossy floor, a mirror</source>
        <translation>Une vraie surface de la photo qui réfléchit : un sol brillant, un miroir</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="416"/>
        <source>&lt;b&gt;New models&lt;/b&gt;</source>
        <translation>&lt;b&gt;Nouveaux modèles&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="420"/>
        <source>The height a model gets when its file does not state its unit (OBJ, PLY, 3DS) or states an absurd size</source>
        <translation>La hauteur que reçoit un modèle quand son fichier n&apos;indique pas d&apos;unité (OBJ, PLY, 3DS) ou une taille absurde</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="479"/>
        <source>No object selected</source>
        <translation>Aucun objet sélectionné</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="486"/>
        <source>&lt;b&gt;Object %1&lt;/b&gt; (%2)</source>
        <translation>&lt;b&gt;Objet %1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="490"/>
        <source>%1 × %2 × %3 m</source>
        <translation>%1 × %2 × %3 m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="494"/>
        <source>– (the scene is being prepared)</source>
        <translation>– (la scène est en préparation)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="538"/>
        <source>Object colour</source>
        <translation>Couleur de l&apos;objet</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ResponseCurveView</name>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="63"/>
        <source>code (up: stops above mid-grey)</source>
        <translation>code (en hauteur : diaphragmes au-dessus du gris moyen)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::ResponseDock</name>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="124"/>
        <source>Uses the standard sRGB curve, as chosen in the list.</source>
        <translation>Utilise la courbe sRGB standard, choisie dans la liste.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="126"/>
        <source>Uses a straight (linear) curve, as chosen in the list: the photo&apos;s values are read as light directly.</source>
        <translation>Utilise une courbe droite (linéaire), choisie dans la liste : les valeurs de la photo sont lues directement comme de la lumière.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="129"/>
        <source>Uses the curve given in the scene file.</source>
        <translation>Utilise la courbe indiquée dans le fichier de scène.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="122"/>
        <source>The photo already holds light values (EXR/HDR): it needs no curve.</source>
        <translation>La photo contient déjà des valeurs de lumière (EXR/HDR) : elle n&apos;a besoin d&apos;aucune courbe.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="132"/>
        <source>Kept the standard sRGB curve: the photo does not show enough to estimate its own tone curve.</source>
        <translation>La courbe sRGB standard est conservée : la photo n&apos;en montre pas assez pour estimer sa propre courbe de tons.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="137"/>
        <source>Kept the standard sRGB curve: the room&apos;s lighting explains the photo better with it than with the curve estimated from the photo.</source>
        <translation>La courbe sRGB standard est conservée : l&apos;éclairage de la pièce explique mieux la photo avec elle qu&apos;avec la courbe estimée à partir de la photo.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="141"/>
        <source>Kept the standard sRGB curve: the photo&apos;s noise does not show a different tone curve clearly.</source>
        <translation>La courbe sRGB standard est conservée : le bruit de la photo ne montre pas clairement une autre courbe de tons.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="144"/>
        <source>Kept the standard sRGB curve: the photo&apos;s edges do not show a different tone curve clearly.</source>
        <translation>La courbe sRGB standard est conservée : les contours de la photo ne montrent pas clairement une autre courbe de tons.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="147"/>
        <source>Uses the tone curve estimated from the photo&apos;s noise; it differs from the standard sRGB curve (dashed).</source>
        <translation>Utilise la courbe de tons estimée d&apos;après le bruit de la photo ; elle diffère de la courbe sRGB standard (en pointillés).</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="150"/>
        <source>Uses the tone curve estimated from the photo&apos;s edges; it differs from the standard sRGB curve (dashed).</source>
        <translation>Utilise la courbe de tons estimée d&apos;après les contours de la photo ; elle diffère de la courbe sRGB standard (en pointillés).</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="160"/>
        <source>If the inserted objects look too bright or too flat against the room, choose sRGB in the list above and compare.</source>
        <translation>Si les objets insérés paraissent trop clairs ou trop plats par rapport à la pièce, choisissez sRGB dans la liste ci-dessus et comparez.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="163"/>
        <source>If the photo was edited, or comes from a phone with strong contrast, its curve may still differ: choose Linear in the list above (it reads the photo&apos;s contrast as softer) and compare the objects&apos; shading.</source>
        <translation>Si la photo a été retouchée, ou vient d&apos;un téléphone au contraste marqué, sa courbe peut tout de même différer : choisissez Linéaire dans la liste ci-dessus (elle lit le contraste de la photo plus doux) et comparez l&apos;ombrage des objets.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="173"/>
        <source>Curve: %1</source>
        <translation>Courbe : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="176"/>
        <source>Estimated from the photo&apos;s noise (%1 levels) in %2 ms.</source>
        <translation>Estimée d&apos;après le bruit de la photo (%1 niveaux) en %2 ms.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="180"/>
        <source>Estimated from %1 edges in %2 ms.</source>
        <translation>Estimée d&apos;après %1 contours en %2 ms.</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="277"/>
        <source>Camera Response</source>
        <translation>Réponse de l&apos;appareil</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="278"/>
        <source>Auto (estimated from the photo)</source>
        <translation>Auto (estimée d&apos;après la photo)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="279"/>
        <source>sRGB</source>
        <translation>sRGB</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="280"/>
        <source>Linear</source>
        <translation>Linéaire</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="281"/>
        <source>Explicit (from the scene file)</source>
        <translation>Explicite (du fichier de scène)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="282"/>
        <source>How the photo&apos;s pixel values map to light (camera.response)</source>
        <translation>Comment les valeurs des pixels de la photo correspondent à la lumière (camera.response)</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="284"/>
        <source>Details</source>
        <translation>Détails</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="285"/>
        <source>The curve&apos;s parameters and what the estimate measured</source>
        <translation>Les paramètres de la courbe et ce que l&apos;estimation a mesuré</translation>
    </message>
    <message>
        <location filename="../app/studio/response_dock.cpp" line="310"/>
        <source>Preparing the scene...</source>
        <translation>Préparation de la scène...</translation>
    </message>
    <message>
        <source>
Estimated from the photo&apos;s noise (%1 levels) in %2 ms.</source>
        <translation type="vanished">
Estimée à partir du bruit de la photo (%1 niveaux) en %2 ms.</translation>
    </message>
    <message>
        <source>
Estimated from %1 edges in %2 ms.</source>
        <translation type="vanished">
Estimée à partir de %1 arêtes en %2 ms.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::SceneTreeDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="72"/>
        <source>sphere</source>
        <translation>sphère</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="73"/>
        <source>cube</source>
        <translation>cube</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="98"/>
        <source>table top or step</source>
        <translation>dessus de table ou marche</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="99"/>
        <source>box</source>
        <translation>boîte</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="100"/>
        <source>stairs</source>
        <translation>escalier</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="156"/>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="157"/>
        <source>Item</source>
        <translation>Élément</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="157"/>
        <source>Details</source>
        <translation>Détails</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="161"/>
        <source>Room</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="164"/>
        <source>%1 × %2 m, %3 m high</source>
        <translation>%1 × %2 m, %3 m de haut</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="169"/>
        <source>back wall given</source>
        <translation>mur du fond donné</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="169"/>
        <source>estimated</source>
        <translation>estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="172"/>
        <source>Lights</source>
        <translation>Lampes</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="177"/>
        <source>Light %1</source>
        <translation>Lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="178"/>
        <source>outline on the photo</source>
        <translation>contour sur la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="178"/>
        <source>rectangle in 3D</source>
        <translation>rectangle en 3D</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="192"/>
        <source>Shafts</source>
        <translation>Rayons de soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="192"/>
        <source>Shaft %1</source>
        <translation>Rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="193"/>
        <source>sunlit patch and its window</source>
        <translation>tache de soleil et sa fenêtre</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="194"/>
        <source>Surfaces</source>
        <translation>Surfaces</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="194"/>
        <source>Surface %1</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="196"/>
        <source>Occluders</source>
        <translation>Masques d&apos;avant-plan</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="196"/>
        <source>Occluder %1</source>
        <translation>Masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="197"/>
        <source>%1 strokes in front, %2 behind</source>
        <translation>%1 traits devant, %2 derrière</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="201"/>
        <source>Objects</source>
        <translation>Objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="206"/>
        <source>hidden: %1</source>
        <translation>masqué : %1</translation>
    </message>
    <message>
        <source>Object %1</source>
        <translation type="vanished">Objet %1</translation>
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
        <translation>photo</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="18"/>
        <source>response</source>
        <translation>réponse</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="19"/>
        <source>working copy</source>
        <translation>copie de travail</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="20"/>
        <source>camera</source>
        <translation>caméra</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="21"/>
        <source>layout</source>
        <translation>disposition</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="22"/>
        <source>occluders</source>
        <translation>masques d&apos;avant-plan</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="23"/>
        <source>surfaces</source>
        <translation>surfaces</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="24"/>
        <source>room</source>
        <translation>pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="25"/>
        <source>lights</source>
        <translation>lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="26"/>
        <source>shafts</source>
        <translation>rayons de soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="27"/>
        <source>lighting</source>
        <translation>éclairage</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="28"/>
        <source>vignetting</source>
        <translation>vignetage</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="29"/>
        <source>sun ratio</source>
        <translation>rapport d&apos;ombre du soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="30"/>
        <source>refine</source>
        <translation>affinage</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="31"/>
        <source>lighting refit</source>
        <translation>réajustement de l&apos;éclairage</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="36"/>
        <source>response check</source>
        <translation>vérification de la courbe de réponse</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="32"/>
        <source>photo size</source>
        <translation>taille de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="33"/>
        <source>render scene</source>
        <translation>scène de rendu</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="34"/>
        <source>objects</source>
        <translation>objets</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="35"/>
        <source>grain</source>
        <translation>grain</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="38"/>
        <source>gather</source>
        <translation>collecte</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="39"/>
        <source>light fit</source>
        <translation>ajustement des lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="40"/>
        <source>unseen patches</source>
        <translation>zones hors champ</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="41"/>
        <source>retinex</source>
        <translation>Retinex</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="42"/>
        <source>decomposition</source>
        <translation>décomposition</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="43"/>
        <source>direct light</source>
        <translation>lumière directe</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="44"/>
        <source>fit pixels</source>
        <translation>pixels de l&apos;ajustement</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="45"/>
        <source>per-pixel albedo</source>
        <translation>albédo par pixel</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="47"/>
        <source>both candidates, side by side</source>
        <translation>les deux candidats, côte à côte</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="48"/>
        <source>both candidates, one after the other</source>
        <translation>les deux candidats, l’un après l’autre</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="50"/>
        <source>both copies, side by side</source>
        <translation>les deux copies, côte à côte</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="51"/>
        <source>both copies, one after the other</source>
        <translation>les deux copies, l&apos;une après l&apos;autre</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="61"/>
        <source>copy, curve: %1</source>
        <translation>copie, courbe : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="62"/>
        <source>copy, sRGB: %1</source>
        <translation>copie, sRGB : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="63"/>
        <source>sRGB: %1</source>
        <translation>avec sRGB : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="82"/>
        <source>; CPU s: %1</source>
        <translation> ; s CPU : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="91"/>
        <source>%1: skipped, %2</source>
        <translation>%1 : ignorée, %2</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="93"/>
        <source>%1: %2 s, CPU %3 s</source>
        <translation>%1 : %2 s, CPU %3 s</translation>
    </message>
    <message>
        <location filename="../app/studio/stage_text.cpp" line="100"/>
        <source>at %1 x %2 px</source>
        <translation>à %1 x %2 px</translation>
    </message>
</context>
<context>
    <name>inlay::studio::StepsDock</name>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="101"/>
        <source>no photo yet</source>
        <translation>pas encore de photo</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="101"/>
        <source>Open Photo…</source>
        <translation>Ouvrir une photo…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="102"/>
        <source>the box is yours</source>
        <translation>la boîte est la vôtre</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="104"/>
        <source>estimated: check that the back wall&apos;s corners sit on the room&apos;s corners</source>
        <translation>estimée : vérifiez que les coins du mur du fond sont sur ceux de la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="105"/>
        <source>Accept the Box</source>
        <translation>Accepter la boîte</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="106"/>
        <source>being estimated…</source>
        <translation>en cours d&apos;estimation…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="108"/>
        <source>not found: drag the back wall&apos;s corners onto the room&apos;s corners</source>
        <translation>introuvable : faites glisser les coins du mur du fond sur ceux de la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="113"/>
        <source>none: objects are lit by gathered light only</source>
        <translation>aucune : les objets ne sont éclairés que par la lumière recueillie</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="113"/>
        <source>Outline a Light</source>
        <translation>Détourer une lumière</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/steps_dock.cpp" line="115"/>
        <source>%n outlined</source>
        <translation>
            <numerusform>%n détourée</numerusform>
            <numerusform>%n détourées</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="119"/>
        <source>none yet (or drag one from the Library)</source>
        <translation>aucun pour l&apos;instant (ou faites-en glisser un de la Bibliothèque)</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="119"/>
        <source>Insert Model…</source>
        <translation>Insérer un modèle…</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/steps_dock.cpp" line="121"/>
        <source>%n in the photo</source>
        <translation>
            <numerusform>%n dans la photo</numerusform>
            <numerusform>%n dans la photo</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="124"/>
        <source>not yet</source>
        <translation>pas encore</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="124"/>
        <source>Render Final Image…</source>
        <translation>Rendre l&apos;image finale…</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="126"/>
        <source>written to %1</source>
        <translation>écrite dans %1</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="156"/>
        <source>Steps</source>
        <translation>Étapes</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="157"/>
        <source>Room</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="157"/>
        <source>Lights</source>
        <translation>Lumières</translation>
    </message>
    <message>
        <location filename="../app/studio/steps_dock.cpp" line="157"/>
        <source>Objects</source>
        <translation>Objets</translation>
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
        <translation>Faites glisser un objet ou un coin du mur du fond.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="324"/>
        <source>Click around a light; click the first point (or press Enter) to close.</source>
        <translation>Cliquez autour d’une lampe ; cliquez sur le premier point (ou appuyez sur Entrée) pour fermer.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="326"/>
        <source>Now drag a box around the window the sunlight comes through.</source>
        <translation>Tracez maintenant un cadre autour de la fenêtre par où entre le soleil.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="327"/>
        <source>Drag a box around the patch of sunlight.</source>
        <translation>Tracez un cadre autour de la tache de soleil.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="330"/>
        <source>Click the floor straight below the first point of the outline.</source>
        <translation>Cliquez sur le sol juste en dessous du premier point du contour.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="331"/>
        <source>Click around the top of a table or step; click the first point to close.</source>
        <translation>Cliquez autour du dessus d&apos;une table ou d&apos;une marche ; cliquez sur le premier point pour fermer.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="333"/>
        <source>Left drag over the thing in front, right drag over what is behind it; Enter starts another occluder.</source>
        <translation>Glissez avec le bouton gauche sur ce qui est devant, avec le droit sur ce qui est derrière ; Entrée commence un autre masque.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="339"/>
        <source>Drag along an edge that runs in the %1 direction (keys X, Y, Z choose it).</source>
        <translation>Faites glisser le long d’une arête dans la direction %1 (les touches X, Y, Z la choisissent).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="341"/>
        <source>Now drag along a second edge in the %1 direction.</source>
        <translation>Faites maintenant glisser le long d’une deuxième arête dans la direction %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="437"/>
        <source>Back wall (yours)</source>
        <translation>Mur du fond (le vôtre)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="437"/>
        <source>Back wall (estimated)</source>
        <translation>Mur du fond (estimé)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="525"/>
        <source>%1 px</source>
        <translation>%1 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="565"/>
        <source>%1: %2 px</source>
        <translation>%1 : %2 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="598"/>
        <source>Light %1</source>
        <translation>Lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="612"/>
        <source>Shaft %1</source>
        <translation>Rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="627"/>
        <source>Surface %1</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="688"/>
        <source>%1 hidden</source>
        <translation>%1 masqué</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="781"/>
        <source>Preparing the scene…</source>
        <translation>Préparation de la scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="783"/>
        <source>The scene could not be prepared: %1</source>
        <translation>La scène n&apos;a pas pu être préparée : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="787"/>
        <source>Open a scene or a photo (File menu).</source>
        <translation>Ouvrez une scène ou une photo (menu Fichier).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="790"/>
        <source>Before: the photo without objects</source>
        <translation>Avant : la photo sans les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="822"/>
        <source>Vanishing points: x %1, y %2, z %3 (confidence)</source>
        <translation>Points de fuite : x %1, y %2, z %3 (confiance)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="826"/>
        <source>Focal length %1 px (%2–%3 px)</source>
        <translation>Focale %1 px (%2–%3 px)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="837"/>
        <source>The whole warnings: the Log tab (View ▸ Log); this text: View ▸ Vanishing Lines and Confidence</source>
        <translation>Les avertissements en entier : l’onglet Journal (Affichage ▸ Journal) ; ce texte : Affichage ▸ Lignes de fuite et confiance</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="892"/>
        <source>Before</source>
        <translation>Avant</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="892"/>
        <source>After</source>
        <translation>Après</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="979"/>
        <source>the left wall</source>
        <translation>le mur de gauche</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="980"/>
        <source>the right wall</source>
        <translation>le mur de droite</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="981"/>
        <source>the back wall</source>
        <translation>le mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="982"/>
        <source>the wall behind the camera</source>
        <translation>le mur derrière l&apos;appareil</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="983"/>
        <source>Its back against %1 (hold Shift to place it freely).</source>
        <translation>Le dos contre %1 (maintenez Maj pour le placer librement).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1004"/>
        <source>Turned %1°</source>
        <translation>Tourné à %1°</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1014"/>
        <source>Height %1 m</source>
        <translation>Hauteur %1 m</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1047"/>
        <source>An outline needs at least three points.</source>
        <translation>Un contour demande au moins trois points.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="972"/>
        <location filename="../app/studio/viewport.cpp" line="1370"/>
        <source>Cannot place the object here: %1</source>
        <translation>Impossible de placer l&apos;objet ici : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="1303"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Chaque ligne doit mesurer au moins deux pixels.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/studio/main.cpp" line="81"/>
        <source>Insert synthetic objects into a photograph.</source>
        <translation>Insérer des objets de synthèse dans une photographie.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="86"/>
        <source>A scene file (.json) or a photo; none: the example.</source>
        <translation>Un fichier de scène (.json) ou une photo ; aucun : l&apos;exemple.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="90"/>
        <source>Grab the window to &lt;file&gt; once rendered, then exit.</source>
        <translation>Capturer la fenêtre dans &lt;file&gt; une fois rendue, puis quitter.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="94"/>
        <source>Samples per pixel to wait for (default 4).</source>
        <translation>Échantillons par pixel à attendre (4 par défaut).</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="98"/>
        <source>Instead: render seconds of the shown frame to wait for.</source>
        <translation>À la place : secondes de rendu de l&apos;image affichée à attendre.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="102"/>
        <source>Show the Log dock across the bottom of the window.</source>
        <translation>Afficher le journal sur toute la largeur du bas de la fenêtre.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="105"/>
        <source>Restore unsaved work left by a crash without asking.</source>
        <translation>Restaurer sans demander le travail non enregistré laissé par un plantage.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="108"/>
        <source>Insert the model &lt;file&gt; into the scene once it is prepared.</source>
        <translation>Insérer le modèle &lt;file&gt; dans la scène dès qu’elle est préparée.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="127"/>
        <source>Give at most one file.</source>
        <translation>Donnez au plus un fichier.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="134"/>
        <location filename="../app/studio/main.cpp" line="142"/>
        <source>expected a number &gt;= 0</source>
        <translation>un nombre &gt;= 0 est attendu</translation>
    </message>
</context>
</TS>
